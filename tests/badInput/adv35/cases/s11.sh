#!/bin/bash
# s11: blast: maxDeltaT 1e-25 with adjustTimeStep yes
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict maxDeltaT 1e-25
timeout 60 cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
