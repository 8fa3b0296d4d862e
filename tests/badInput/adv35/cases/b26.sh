#!/bin/bash
# b26: blast: case path with unicode
. "$(dirname "$0")/../lib.sh"
blast; cd ..; mv blast 'blâst'; cd 'blâst'
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
