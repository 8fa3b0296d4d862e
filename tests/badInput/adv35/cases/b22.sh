#!/bin/bash
# b22: blast: fsiProperties unknown top-level keyword (couplng)
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^coupling/couplng/' constant/fsiProperties
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
