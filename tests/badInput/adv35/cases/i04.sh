#!/bin/bash
# i04: ind: radius given twice (different values)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/radius 22.5e-6;\nradius 30e-6;/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
