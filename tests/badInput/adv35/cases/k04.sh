#!/bin/bash
# k04: ind: restart.h5 truncated to 50 %, restart
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; truncate -s $(($(stat -c%s postProcessing/indentation/restart.h5)*50/100)) postProcessing/indentation/restart.h5
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
