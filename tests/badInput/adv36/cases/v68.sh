#!/bin/bash
# v68: blast: one digit of a row of solidProbes.dat changed (a structurally whole row, as bit rot or an edit), then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; f=postProcessing/solidProbes/0/solidProbes.dat; sed -n 20p $f | cut -c1-60; sed -i '20s/^\([^ ]* [-]*[0-9]\.[0-9]\)[0-9]/\19/' $f; sed -n 20p $f | cut -c1-60
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
