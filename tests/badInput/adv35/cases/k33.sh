#!/bin/bash
# k33: ind: force.dat with 40 zero bytes at 30 %, restart (appended row)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; f=postProcessing/indentation/force.dat; dd if=/dev/zero of=$f bs=1 count=40 seek=$(($(stat -c%s $f)*30/100)) conv=notrunc 2>/dev/null
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -5; tail -1 log.run; echo "rc=$rc"; tr -d '\000' < postProcessing/indentation/force.dat | cmp -s - postProcessing/indentation/force.dat && echo "no zero bytes left in force.dat" || echo "force.dat still holds zero bytes"
