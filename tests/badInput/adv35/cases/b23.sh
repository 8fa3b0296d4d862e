#!/bin/bash
# b23: blast: motionDistance negative
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/motionDistance -5e-6
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
