#!/bin/bash
# v09: sod: restart (endTime 0.008) after the diaphragm x0 was moved (setRiemannProblem input of the initial state)
. "$(dirname "$0")/../lib.sh"
sodDone; sed -i 's/^x0 .*/x0 0.1;/; s/^endTime .*/endTime 0.008;/' system/riemannProblemDict
rhoRiemannFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -6; tail -1 log.run; echo "rc=$rc"
