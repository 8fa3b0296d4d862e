#!/bin/bash
# b24: blast: writeFormat ascii (legal variant: must run)
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict writeFormat ascii
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
