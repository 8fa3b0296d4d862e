#!/bin/bash
# o02: ind: -overwrite over a finished case with a typo in indenterProperties
. "$(dirname "$0")/../lib.sh"
indDone; sums > ../before; sed -i 's/^radius /radus /' constant/indenterProperties
cellIndentationFoam -overwrite 2>&1 | tail -5; echo "rc=${PIPESTATUS[0]}"; sums | grep -v indenterProperties > ../after; grep -v indenterProperties ../before | cmp -s - ../after && echo "results unchanged" || echo "RESULTS CHANGED"
