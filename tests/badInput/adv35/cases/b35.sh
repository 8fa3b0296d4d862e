#!/bin/bash
# b35: blast: misspelt keyword in the water's mieGruneisenCoeffs (Gama0)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/Gamma0  0.1;/Gama0 0.1;/' constant/thermophysicalProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
