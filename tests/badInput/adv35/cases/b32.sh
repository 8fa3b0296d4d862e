#!/bin/bash
# b32: blast: 0/p pulse table given twice entry uniformValue duplicated (two tables, different amplitudes)
. "$(dirname "$0")/../lib.sh"
blast; sed -i '0,/uniformValue    table/s//uniformValue constant 1e6;\n        uniformValue    table/' 0/p; grep -n uniformValue 0/p
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
