#!/bin/bash
# b10: blast: Gamma0 negative in thermophysicalProperties
. "$(dirname "$0")/../lib.sh"
blast; setd constant/thermophysicalProperties mieGruneisenCoeffs/Gamma0 -0.1
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
