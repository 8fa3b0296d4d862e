#!/bin/bash
# b40: blast: fsiProperties axisDirection flipped (0 -1 0): the cell upside down against the fluid
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/axisDirection '(0 -1 0)'
cellBlastFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"
