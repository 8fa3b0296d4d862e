#!/bin/bash
# b25: blast: case path with a space
. "$(dirname "$0")/../lib.sh"
blast; cd ..; mv blast 'bl ast'; cd 'bl ast'
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
