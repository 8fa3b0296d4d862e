#!/bin/bash
# b14: blast: reconstruct(p) unknown scheme
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/reconstruct(p)      MUSCL;/reconstruct(p) MUSLC;/' system/fvSchemes
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
