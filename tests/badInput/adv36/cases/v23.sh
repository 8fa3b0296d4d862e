#!/bin/bash
# v23: blast: the latest time 2e-9 copied by hand to 3e-9 with its marker, then a restart from 3e-9
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r 2e-09 3e-09; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 4e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A8 FATAL log.r | head -10
