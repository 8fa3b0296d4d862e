#!/bin/bash
# v15: blast: solidProbes.dat deleted, then a restart
. "$(dirname "$0")/../lib.sh"
blastDone; rm postProcessing/solidProbes/0/solidProbes.dat; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8; ls postProcessing/solidProbes/*
