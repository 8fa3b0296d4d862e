#!/bin/bash
# v61: probes at restart: fluidProbes enabled false
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; sed -i 's/type            movingMeshProbes;/& enabled false;/' system/controlDict; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
