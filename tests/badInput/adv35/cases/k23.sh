#!/bin/bash
# k23: blast: solid/solid.xmf truncated, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; truncate -s $(($(stat -c%s solid/solid.xmf)*50/100)) solid/solid.xmf
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; tail -c 200 solid/solid.xmf
