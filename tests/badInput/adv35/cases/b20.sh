#!/bin/bash
# b20: blast: writeInterval 0
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict writeInterval 0
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
