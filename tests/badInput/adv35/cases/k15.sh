#!/bin/bash
# k15: blast: 2e-09/polyMesh/points truncated, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; truncate -s $(($(stat -c%s 2e-09/polyMesh/points)*80/100)) 2e-09/polyMesh/points
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
