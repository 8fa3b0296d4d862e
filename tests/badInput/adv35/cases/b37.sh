#!/bin/bash
# b37: blast: fvSolution riemann{} with a misspelt keyword (timeSchem, defaulted)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/timeScheme      SSPRK3;/timeSchem SSPRK2;/' system/fvSolution
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
