#!/bin/bash
# o14: ind: -overwrite over a finished case with maxDeltaT 1e-5 (the new run fails at its first step): what is left of the earlier results
. "$(dirname "$0")/../lib.sh"
indDone; sums > ../before; setd constant/indenterProperties holdDeltaT0 1e-5; setd constant/indenterProperties maxDeltaT 1e-5
cellIndentationFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -A2 FATAL log.ow | head -3
sums | grep -v indenterProperties > ../after; grep -v indenterProperties ../before | diff - ../after && echo "results unchanged"; ls -la postProcessing/indentation
