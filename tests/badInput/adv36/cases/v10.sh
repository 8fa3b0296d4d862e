#!/bin/bash
# v10: blast: a partial last row (no end of line) appended to coupling.dat, as a kill inside a write leaves, then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; printf '2.0001e-09 3 1e-5' >> postProcessing/fsi/0/coupling.dat; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8; tail -3 postProcessing/fsi/0/coupling.dat | cut -c1-80
