#!/bin/bash
# r30: blast: restart with the 0/ directory's p changed (amplitude): 0/ is not read at a restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; sed -i 's/(1e-10    50000000)/(1e-10 60000000)/' 0/p
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
