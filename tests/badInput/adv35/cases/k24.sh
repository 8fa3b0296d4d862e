#!/bin/bash
# k24: ind: solid.h5 1000 bytes zeroed at 90 % then restart (appended row)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; dd if=/dev/zero of=postProcessing/indentation/solid.h5 bs=1 count=1000 seek=$(($(stat -c%s postProcessing/indentation/solid.h5)*90/100)) conv=notrunc 2>/dev/null
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
