#!/bin/bash
# i03: ind: radius 1e400
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius 1e400;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
