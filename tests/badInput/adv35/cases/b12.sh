#!/bin/bash
# b12: blast: 0/p pulse table times not increasing
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/(1e-10    50000000)/(3e-9 50000000)/; s/(5e-09    50000000)/(2e-9 50000000)/' 0/p; grep -A7 'table' 0/p | head -8
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
