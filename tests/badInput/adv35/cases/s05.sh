#!/bin/bash
# s05: ind: hold with holdDeltaT0 1e-15 and holdGrowth 1.0000001, maxDeltaT 1e-15
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdDeltaT0 1e-15; setd constant/indenterProperties holdGrowth 1.0000001; setd constant/indenterProperties maxDeltaT 1e-15
timeout 60 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
