#!/bin/bash
# b13: blast: 0/T negative internal field
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^internalField .*/internalField uniform -10;/' 0/T
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
