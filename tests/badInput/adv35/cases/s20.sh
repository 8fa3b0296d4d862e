#!/bin/bash
# s20: ind: holdGrowth 10 (its range's top), holdDeltaT0 = maxDeltaT = 1e-3 s: the root cause of s15 predicts an overflow after ln(DBL_MAX/1e-3)/ln(10) = 311 steps of row A (t = 0.311 s), about 15 s of run
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdGrowth 10; setd constant/indenterProperties holdDeltaT0 1e-3; setd constant/indenterProperties maxDeltaT 1e-3
timeout 250 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A4 "FATAL\|#0" log.run | head -6; echo "rc=$rc (136 = SIGFPE)"; tail -1 postProcessing/indentation/force.dat
