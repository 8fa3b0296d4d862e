#!/bin/bash
# s12: blast: solidSubcycles 1000000
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties coupling/solidSubcycles 1000000
timeout 60 cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
