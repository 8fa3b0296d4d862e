#!/bin/bash
# v57: probes at restart: fluidProbes probeLocations changed (one point moved)
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; sed -i 's/(1e-7 10e-6 0)/(2e-7 10e-6 0)/' system/controlDict; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
