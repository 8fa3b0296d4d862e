#!/bin/bash
# v13: blast: 16 zero bytes in the middle of interfaceMaxima.dat, then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; f=$(ls postProcessing/solidInterfaces/0/*.dat | head -1); echo $f; s=$(stat -c%s $f); dd if=/dev/zero of=$f bs=1 seek=$((s/2)) count=16 conv=notrunc 2>/dev/null; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8
