#!/bin/bash
# s04: ind: maxDepthIncrement 1e-15 (1e9 steps)
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties maxDepthIncrement 1e-15
timeout 60 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
