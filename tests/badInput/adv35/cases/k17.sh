#!/bin/bash
# k17: ind: restart.h5 deleted (results kept), restart latestTime
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; rm postProcessing/indentation/restart.h5; cp postProcessing/indentation/force.dat ../f
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; cmp postProcessing/indentation/force.dat ../f && echo "force.dat unchanged"
