#!/bin/bash
# v08: sod: riemannProblemDict endTime misspelt (endTme) while controlDict uses $endTime
. "$(dirname "$0")/../lib.sh"
sod; sed -i 's/^endTime /endTme /' system/riemannProblemDict
rhoRiemannFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -6; tail -1 log.run; echo "rc=$rc"
