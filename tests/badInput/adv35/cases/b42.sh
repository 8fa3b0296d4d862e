#!/bin/bash
# b42: blast: solidProperties mesh scale 1e-6 (the cell a million times smaller)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/scale       1;/scale 1e-6;/' constant/solidProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"
