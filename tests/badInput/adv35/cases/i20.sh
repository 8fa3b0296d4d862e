#!/bin/bash
# i20: ind: fixed component 2 in axisymmetric
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(axis 0)/(axis 0) (axis 2)/' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
