#!/bin/bash
# k10: blast: solid/solid.h5 4000 bytes zeroed at 80 %, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; dd if=/dev/zero of=solid/solid.h5 bs=1 count=4000 seek=$(($(stat -c%s solid/solid.h5)*80/100)) conv=notrunc 2>/dev/null
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
