#!/bin/bash
# k06: ind: peaks.dat deleted, restart
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; rm postProcessing/indentation/peaks.dat
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls postProcessing/indentation
