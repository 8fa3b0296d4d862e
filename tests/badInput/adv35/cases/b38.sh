#!/bin/bash
# b38: blast: fvSolution riemann{} viscous given twice (false, true)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/viscous         false;/viscous false; viscous true;/' system/fvSolution
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
