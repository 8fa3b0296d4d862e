#!/bin/bash
# k30: blast: the middle time 1e-09 deleted, restart latestTime (legit)
. "$(dirname "$0")/../lib.sh"
blastDone; rm -rf 1e-09; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
