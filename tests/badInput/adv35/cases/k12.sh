#!/bin/bash
# k12: blast: 2e-09/.writeCommitted removed, restart latestTime
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; ls -a 2e-09 | head -3; rm -f 2e-09/.writeCommitted
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls
grep -i "restart\|from time\|Continu\|commit" log.run | head -5
