#!/bin/bash
# r07: ind: restart, appended row + fieldWriteInterval changed 0 -> 0.5
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's/^fieldWriteInterval .*/fieldWriteInterval 0.5;/' system/controlDict
cellIndentationFoam 2>&1 | grep -A6 "FATAL" | head -9; echo "rc=${PIPESTATUS[0]}"; h5ls postProcessing/indentation/solid.h5 | head
