#!/bin/bash
# s06: blast: adjustTimeStep no, deltaT 1e-25 (1e16 steps)
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict adjustTimeStep no; setd system/controlDict deltaT 1e-25
timeout 60 cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
