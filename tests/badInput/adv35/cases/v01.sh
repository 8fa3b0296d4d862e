#!/bin/bash
# v01: sod: riemannProblemDict left p negative (ideal gas)
. "$(dirname "$0")/../lib.sh"
sod; setd system/riemannProblemDict left/p -1e5
setRiemannProblem > log.sr 2>&1; rc=$?; grep -A4 "FATAL" log.sr | head -6; tail -1 log.sr; echo "rc=$rc"
