#!/bin/bash
# b09: blast: endTime below startTime (negative)
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime -1e-9
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
