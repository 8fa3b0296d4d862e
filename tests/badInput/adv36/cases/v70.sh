#!/bin/bash
# v70: blast: cellBlastFoam -overwrite from the middle time (startTime 1e-9 of a finished 2e-9 run, inputs unchanged), then a plain restart of what was put back
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i 's/^startTime .*/startTime 1e-9;/' system/controlDict; sums > ../before
cellBlastFoam -overwrite > log.ow 2>&1; echo "-overwrite from 1e-9 rc=$?"; grep -a -A2 "FATAL" log.ow | head -3 | cut -c1-300; grep -a "put back" log.ow | cut -c1-200
echo "files the refused run left: $(find postProcessing solid -newer ../before -type f | tr '\n' ' ')"
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A2 FATAL log.r | head -3 | cut -c1-400
