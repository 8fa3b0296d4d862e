#!/bin/bash
# r08: ind: restart, appended row + the last-run row's stage label renamed (C1 -> C9)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's/(C1  unload/(C9  unload/' constant/indenterProperties
cellIndentationFoam 2>&1 | grep -A6 "FATAL" | head -9; echo "rc=${PIPESTATUS[0]}"
