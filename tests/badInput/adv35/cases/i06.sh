#!/bin/bash
# i06: ind: protocol amount negative
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(A   load    0.3e-6  0.3e-6)/(A load 0.3e-6 -0.3e-6)/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
