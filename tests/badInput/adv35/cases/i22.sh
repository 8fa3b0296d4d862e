#!/bin/bash
# i22: ind: mesh scale 0
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/scale       1;/scale 0;/' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
