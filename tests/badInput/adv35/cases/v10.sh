#!/bin/bash
# v10: sod: restart (endTime 0.008) with riemannSolver HLLC -> HLL in fvSolution
. "$(dirname "$0")/../lib.sh"
sodDone; sed -i 's/riemannSolver *HLLC;/riemannSolver HLL;/' system/fvSolution; grep -c "HLL;" system/fvSolution; sed -i 's/^endTime .*/endTime 0.008;/' system/riemannProblemDict
rhoRiemannFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -6; tail -1 log.run; echo "rc=$rc"
