#!/bin/bash
# k13: blast: solidProbes file truncated mid-line, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; f=$(ls postProcessing/solidProbes/0/*); truncate -s $(($(stat -c%s $f)*90/100)) $f
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls postProcessing/solidProbes/; tail -c 300 $f
echo "--- solidProbes rows of a different column count:"; grep -v '^#' $f | awk 'NR==1{n=NF} NF!=n{print "BAD row " NR ": " NF " columns (first " n ")"}' | head
