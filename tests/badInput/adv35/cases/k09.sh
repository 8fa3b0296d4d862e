#!/bin/bash
# k09: blast: solid/solid.h5 truncated to 70 %, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; truncate -s $(($(stat -c%s solid/solid.h5)*70/100)) solid/solid.h5
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
