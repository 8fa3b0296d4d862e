#!/bin/bash
# b05: blast: axisDirection zero vector
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/axisDirection '(0 0 0)'
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
