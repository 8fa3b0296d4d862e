#!/bin/bash
# r28: ind: restart with a row inserted before the already-run rows
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; sed -i 's/(A   load    0.3e-6  0.3e-6)/(A0 hold 0 0.5)\n    (A   load    0.3e-6  0.3e-6)/' constant/indenterProperties
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"
