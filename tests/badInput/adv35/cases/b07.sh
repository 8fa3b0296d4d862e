#!/bin/bash
# b07: blast: deltaT negative
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict deltaT -1e-12
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
