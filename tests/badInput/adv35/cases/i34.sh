#!/bin/bash
# i34: ind: maxDepthIncrement inf
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^maxDepthIncrement .*/maxDepthIncrement inf;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
