#!/bin/bash
# v02: sod: riemannProblemDict direction (0 0 0)
. "$(dirname "$0")/../lib.sh"
sod; setd system/riemannProblemDict direction '(0 0 0)'
setRiemannProblem > log.sr 2>&1; rc=$?; grep -A4 "FATAL" log.sr | head -6; tail -1 log.sr; echo "rc=$rc"
