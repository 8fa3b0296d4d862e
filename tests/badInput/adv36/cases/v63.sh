#!/bin/bash
# v63: probes at restart: fluidProbes writeInterval 1 -> 2 (an output setting, documented as accepted): then the restart's own log check
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; blastEnd 3e-9 1e-9; sed -i '0,/writeInterval   1;/s//writeInterval 2;/' system/controlDict; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
blastEnd 4e-9 1e-9; cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A4 FATAL log.r | head -6 | cut -c1-300
