#!/bin/bash
# b28: blast: fluid probes interpolationScheme misspelt
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/interpolationScheme cellPoint;/interpolationScheme cellPont;/' system/controlDict
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
