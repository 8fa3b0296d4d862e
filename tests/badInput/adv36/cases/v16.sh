#!/bin/bash
# v16: blast: an extra column in a middle row of solidProbes.dat, then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; f=postProcessing/solidProbes/0/solidProbes.dat; sed -i '8s/$/ 12345/' $f; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8
