#!/bin/bash
# r29: blast: restart with endTime extended and writeInterval changed (legit: continues)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd system/controlDict writeInterval 5e-10
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls -d [0-9]*
