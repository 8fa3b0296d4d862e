#!/bin/bash
# r01: ind: finished, restart latestTime with one appended row (baseline: continues)
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties
cellIndentationFoam 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"; tail -2 postProcessing/indentation/force.dat
