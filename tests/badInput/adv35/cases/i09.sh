#!/bin/bash
# i09: ind: protocol row with 3 items
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(B   hold    0       1)/(B hold 1)/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
