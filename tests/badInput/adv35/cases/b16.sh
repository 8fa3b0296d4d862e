#!/bin/bash
# b16: blast: interfaceProbe heightFraction 1.5
. "$(dirname "$0")/../lib.sh"
blast; setd constant/solidProperties interfaceProbe/heightFraction 1.5
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
