#!/bin/bash
# o06: blast: startFrom startTime with startTime 1e-09 (an existing middle time) over a finished case
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before; setd system/controlDict startTime 1e-09
cellBlastFoam 2>&1 | grep -i -A3 "error\|refus\|overwrite" | head; echo "rc=${PIPESTATUS[0]}"; ls; sums > ../after; cmp -s ../before ../after && echo "files unchanged" || { echo "FILES CHANGED"; diff ../before ../after | head; }
