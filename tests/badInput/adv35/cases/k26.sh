#!/bin/bash
# k26: blast: 2e-09/.writeCommitted removed AND 64 bytes of 2e-09/p zeroed, restart latestTime
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
rm -f 2e-09/.writeCommitted; dd if=/dev/zero of=2e-09/p bs=1 count=64 seek=$(($(stat -c%s 2e-09/p)*70/100)) conv=notrunc 2>/dev/null
cellBlastFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; grep -i "Restarting from" log.run; tail -2 log.run; echo "rc=$rc"
