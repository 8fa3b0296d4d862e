#!/bin/bash
# b29: blast: fluidProbes fields (p) -> (pp) unknown field
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/fields          (p);/fields (pp);/' system/controlDict
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
