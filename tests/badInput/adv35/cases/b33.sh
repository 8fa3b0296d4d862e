#!/bin/bash
# b33: blast: top patch type misspelt in 0/p (uniformFixedValue -> uniformFixedValu)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/type            uniformFixedValue;/type uniformFixedValu;/' 0/p; grep -c uniformFixedValu 0/p
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
