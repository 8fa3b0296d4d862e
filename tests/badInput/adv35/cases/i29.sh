#!/bin/bash
# i29: ind: penaltyFactor 1e-300
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties penaltyFactor 1e-300
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
