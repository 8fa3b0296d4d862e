#!/bin/bash
# b17: blast: interfaces list names an unknown region
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^interfaces .*/interfaces ((membrane cytoplasma));/' constant/solidProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
