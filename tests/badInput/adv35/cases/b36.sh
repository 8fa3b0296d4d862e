#!/bin/bash
# b36: blast: fvSolution riemannSolver misspelt (HLLCC)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/riemannSolver   HLLC;/riemannSolver HLLCC;/' system/fvSolution
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
