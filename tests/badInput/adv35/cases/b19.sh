#!/bin/bash
# b19: blast: dynamicMeshDict missing
. "$(dirname "$0")/../lib.sh"
blast; rm constant/dynamicMeshDict
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
