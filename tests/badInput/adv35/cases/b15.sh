#!/bin/bash
# b15: blast: fluid probe outside the domain
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/(1e-7 10e-6 0)/(1e-7 500e-6 0)/' system/controlDict
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
