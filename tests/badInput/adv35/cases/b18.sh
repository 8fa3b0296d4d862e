#!/bin/bash
# b18: blast: shearViscosity 1 (range [0,1))
. "$(dirname "$0")/../lib.sh"
blast; setd constant/solidProperties shearViscosity 1
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
