#!/bin/bash
# o15: ind: a finished case; run from startTime WITHOUT -overwrite but with maxDeltaT 1e-5 (refused before anything, results intact)
. "$(dirname "$0")/../lib.sh"
indDone; sums > ../before; setd constant/indenterProperties holdDeltaT0 1e-5; setd constant/indenterProperties maxDeltaT 1e-5
cellIndentationFoam > log.ow 2>&1; echo "rc=$?"; grep -A2 FATAL log.ow | head -3
sums | grep -v indenterProperties > ../after; grep -v indenterProperties ../before | diff - ../after && echo "results unchanged"
