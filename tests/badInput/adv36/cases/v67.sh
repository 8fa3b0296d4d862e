#!/bin/bash
# v67: blast: solidProbes.dat deleted, a restart to 3e-9 s, then planeWave on the case: does anything say that the solid probes' rows before 2e-9 s are missing?
. "$(dirname "$0")/../lib.sh"
blastDone; rm postProcessing/solidProbes/0/solidProbes.dat; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; find postProcessing/solidProbes -type f
planeWave -dz 50e-9 > log.pw 2>&1; echo "planeWave rc=$?"; grep -ai "error\|solid_p0\|missing\|start" log.pw | head -4 | cut -c1-300; grep -v "^#" postProcessing/planeWave/0/measures.dat 2>/dev/null | grep solid_p0 | head -1 | cut -c1-200
