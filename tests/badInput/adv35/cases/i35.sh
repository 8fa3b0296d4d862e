#!/bin/bash
# i35: ind: holdDeltaT0 larger than hold time
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties holdDeltaT0 100
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
