#!/bin/bash
# k07: blast: 2e-09/p (binary) 64 bytes zeroed at 70 %, restart
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; dd if=/dev/zero of=2e-09/p bs=1 count=64 seek=$(($(stat -c%s 2e-09/p)*70/100)) conv=notrunc 2>/dev/null
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
