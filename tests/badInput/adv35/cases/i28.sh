#!/bin/bash
# i28: ind: unknown keyword in solidProperties top level (fixd)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^fixed /fixd /' constant/solidProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
