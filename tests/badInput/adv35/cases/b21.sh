#!/bin/bash
# b21: blast: thermophysicalProperties with duplicated C0
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/C0      1450;/C0 1450; C0 1500;/' constant/thermophysicalProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
