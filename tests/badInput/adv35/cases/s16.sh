#!/bin/bash
# s16: ind: maxDepthIncrement 3e-11 m and tolerance 3e-12 m (steps of 1e-4 s in row A, like s15 but through the depth step)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties maxDepthIncrement 3e-11; setd constant/indenterProperties tolerance 3e-12
timeout 250 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A6 "FATAL\|#0" log.run | head -10; echo "rc=$rc (136 = SIGFPE, 124 = still running at 250 s)"; tail -1 postProcessing/indentation/force.dat
