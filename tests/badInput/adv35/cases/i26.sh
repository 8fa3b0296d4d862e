#!/bin/bash
# i26: ind: controlDict startFrom misspelt
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^startFrom .*/startFrom latestTim;/' system/controlDict
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
