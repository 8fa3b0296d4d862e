#!/bin/bash
# r15: blast: restart with a solid material value changed (membrane d0)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; sed -i 's/d0          9.5125e-10;/d0 9.6e-10;/' constant/solidProperties; grep -c "d0 9.6e-10" constant/solidProperties
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"
