#!/bin/bash
# v06: ind: -overwrite failing at its first step (o14's input) with a user's notes.txt and plot.png in postProcessing/indentation
. "$(dirname "$0")/../lib.sh"
indDone; echo mine > postProcessing/indentation/notes.txt; echo png > postProcessing/indentation/plot.png; sums > ../before
setd constant/indenterProperties holdDeltaT0 1e-5; setd constant/indenterProperties maxDeltaT 1e-5
cellIndentationFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -a -A1 FATAL log.ow | head -3
sums > ../after; diff <(grep -v indenterProperties ../before) <(grep -v indenterProperties ../after) && echo "results unchanged"
