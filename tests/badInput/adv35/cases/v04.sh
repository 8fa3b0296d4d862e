#!/bin/bash
# v04: sod: restart latestTime (endTime 0.007 -> 0.008) with the gas gamma changed 1.4 -> 1.3
. "$(dirname "$0")/../lib.sh"
sodDone; sed -i 's/\(gamma \+\)1.4;/\11.3;/' constant/thermophysicalProperties; grep -c "1.3;" constant/thermophysicalProperties; sed -i 's/^endTime .*/endTime 0.008;/' system/riemannProblemDict
rhoRiemannFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -6; tail -1 log.run; echo "rc=$rc"
