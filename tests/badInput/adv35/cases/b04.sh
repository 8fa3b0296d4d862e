#!/bin/bash
# b04: blast: solidFaceSet wrong name
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/solidFaceSet outerSurfac
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
