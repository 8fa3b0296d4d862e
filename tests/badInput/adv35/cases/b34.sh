#!/bin/bash
# b34: blast: 0/U internalField with 1e400
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^internalField .*/internalField uniform (0 1e400 0);/' 0/U
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
