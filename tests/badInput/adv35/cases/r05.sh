#!/bin/bash
# r05: ind: restart, appended row + the included material file swapped (text instead of textFactor4)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's#cellMaterials/textFactor4#cellMaterials/text#' constant/solidProperties
cellIndentationFoam 2>&1 | grep -A6 "FATAL" | head -9; echo "rc=${PIPESTATUS[0]}"
