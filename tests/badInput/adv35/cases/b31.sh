#!/bin/bash
# b31: blast: 0/p pulse table with a nan pressure
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/(1e-10    50000000)/(1e-10 nan)/' 0/p
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
