#!/bin/bash
# k14: blast: fsi/0/coupling.dat truncated to 50 %, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; truncate -s $(($(stat -c%s postProcessing/fsi/0/coupling.dat)*50/100)) postProcessing/fsi/0/coupling.dat
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
echo "--- coupling.dat time column: gaps"; grep -v '^#' postProcessing/fsi/0/coupling.dat | awk '{print $1, $2}' | head -40 | tr '\n' ';'; echo; grep -v '^#' postProcessing/fsi/0/coupling.dat | awk 'NF!=n && n{print "BAD row " NR": " NF" columns"} {n=NF}' | head -3
