#!/bin/bash
# i02: ind: radius nan
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius nan;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
