#!/bin/bash
# r18: blast: restart with fluidProbes locations changed (probe 3 10 um -> 11 um)
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i 's/(1e-7 10e-6 0)/(1e-7 11e-6 0)/' system/controlDict; grep -c "11e-6" system/controlDict; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
cellBlastFoam 2>&1 | grep -iA3 "FATAL\|changed" | head; echo "rc=${PIPESTATUS[0]}"; head -5 postProcessing/fluidProbes/*/p; ls postProcessing/fluidProbes
