#!/bin/bash
# b06: blast: onNonConvergence misspelt
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties coupling/onNonConvergence wran
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
