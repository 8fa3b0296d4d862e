#!/bin/bash
# s13: ind: maxDeltaT 1e-6 and holdDeltaT0 1e-6 (about 2e6 steps: hours); must be refused up front or run (timeout 60 s here)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdDeltaT0 1e-6; setd constant/indenterProperties maxDeltaT 1e-6
timeout 60 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc (124: still running after 60 s)"; wc -l postProcessing/indentation/force.dat
