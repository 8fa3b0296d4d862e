#!/bin/bash
# r03: ind: restart, appended row + contactPatch's tolerance changed
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's/^tolerance .*/tolerance 2e-9;/' constant/indenterProperties
cellIndentationFoam 2>&1 | grep -A6 "FATAL" | head -9; echo "rc=${PIPESTATUS[0]}"
