#!/bin/bash
# b02: blast: coupling tolerance nan
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/tolerance       1e-4;/tolerance nan;/' constant/fsiProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
