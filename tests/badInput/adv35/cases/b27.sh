#!/bin/bash
# b27: blast: output folder solid/ is a regular file (unwritable output)
. "$(dirname "$0")/../lib.sh"
blast; echo user > solid
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; cat solid
