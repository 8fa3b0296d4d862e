#!/bin/bash
# s07: blast: writeInterval 1e-15 (2e6 writes)
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict writeInterval 1e-15
timeout 60 cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls | wc -l
