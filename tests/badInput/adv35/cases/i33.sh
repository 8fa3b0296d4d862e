#!/bin/bash
# i33: ind: protocol stage name with a space-like char / unicode label
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/(B   hold/(Bé hold/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
