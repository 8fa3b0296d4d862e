#!/bin/bash
# i12: ind: maxDeltaT 0
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties maxDeltaT 0
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
