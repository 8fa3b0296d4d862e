#!/bin/bash
# r06: ind: restart, appended row + holdGrowth changed (stepping of holds)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's/^holdGrowth .*/holdGrowth 1.2;/' constant/indenterProperties
cellIndentationFoam 2>&1 | grep -A6 "FATAL" | head -9; echo "rc=${PIPESTATUS[0]}"
