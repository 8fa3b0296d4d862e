#!/bin/bash
# i11: ind: holdGrowth 0.5
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdGrowth 0.5
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
