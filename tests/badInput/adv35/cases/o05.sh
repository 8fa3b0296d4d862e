#!/bin/bash
# o05: blast: -overwrite over finished case with an unknown coupling scheme
. "$(dirname "$0")/../lib.sh"
blastDone; sums | grep -v fsiProperties > ../before; setd constant/fsiProperties coupling/scheme robinn
cellBlastFoam -overwrite 2>&1 | grep -i -A3 "error" | head; echo "rc=${PIPESTATUS[0]}"; sums | grep -v fsiProperties > ../after; cmp -s ../before ../after && echo "results unchanged" || { echo "RESULTS CHANGED"; diff ../before ../after; }
