#!/bin/bash
# s08: ind: fieldWriteInterval 1e-9 (2e9 field writes)
. "$(dirname "$0")/../lib.sh"
ind; setd system/controlDict fieldWriteInterval 1e-9
timeout 60 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls -la postProcessing/indentation/solid.h5
