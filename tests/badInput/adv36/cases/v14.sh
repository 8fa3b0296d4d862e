#!/bin/bash
# v14: blast: fluidProbes/0/p cut in the middle of a row, then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; f=postProcessing/fluidProbes/0/p; s=$(stat -c%s $f); truncate -s $((s*2/3)) $f; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8
