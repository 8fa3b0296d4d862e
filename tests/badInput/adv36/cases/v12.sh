#!/bin/bash
# v12: blast: a middle row of coupling.dat duplicated (the times no longer increase), then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; f=postProcessing/fsi/0/coupling.dat; sed -i '6p' $f; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8
