#!/bin/bash
# i21: ind: fixed node set nonexistent
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(axis 0)/(axes 0)/' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
