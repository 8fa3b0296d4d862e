#!/bin/bash
# b03: blast: fluidPatch wrong name
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/fluidPatch interfac
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
