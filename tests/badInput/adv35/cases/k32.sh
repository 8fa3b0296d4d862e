#!/bin/bash
# k32: ind: peaks.dat with 30 zero bytes in its middle, restart (appended row)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; f=postProcessing/indentation/peaks.dat; dd if=/dev/zero of=$f bs=1 count=30 seek=$(($(stat -c%s $f)/2)) conv=notrunc 2>/dev/null
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"; od -c postProcessing/indentation/peaks.dat | grep -c '\\0'
