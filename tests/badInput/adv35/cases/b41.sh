#!/bin/bash
# b41: blast: fsiProperties axisOrigin shifted 0.02 um up (within mapTolerance)
. "$(dirname "$0")/../lib.sh"
blast; setd constant/fsiProperties interface/axisOrigin '(0 2e-8 0)'
cellBlastFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"; grep -i "map check\|gap" log.run | head -2 | cut -c1-200
