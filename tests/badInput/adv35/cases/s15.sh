#!/bin/bash
# s15: ind: holdDeltaT0 1e-4 and maxDeltaT 1e-4 (both in range): sigFpe in solid::IndentationDriver::run() at t = 0.177 s of row A (about 70 s of run)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdDeltaT0 1e-4; setd constant/indenterProperties maxDeltaT 1e-4
timeout 280 cellIndentationFoam > log.run 2>&1; rc=$?; grep -a -A6 "FATAL\|sigFpe\|#0" log.run | head -10; echo "rc=$rc (136 = SIGFPE)"; tail -1 postProcessing/indentation/force.dat
