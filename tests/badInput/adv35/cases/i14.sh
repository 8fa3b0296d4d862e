#!/bin/bash
# i14: ind: fieldWriteInterval negative
. "$(dirname "$0")/../lib.sh"
ind; setd system/controlDict fieldWriteInterval -1
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
