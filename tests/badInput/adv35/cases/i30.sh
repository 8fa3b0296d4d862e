#!/bin/bash
# i30: ind: tolerance 0
. "$(dirname "$0")/../lib.sh"
ind; setd constant/indenterProperties tolerance 0
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
