#!/bin/bash
# i17: ind: mesh file truncated at half
. "$(dirname "$0")/../lib.sh"
ind; f=constant/cell.msh; truncate -s $(($(stat -c%s $f)/2)) $f
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
