#!/bin/bash
# k16: ind: solid.xmf deleted, restart
. "$(dirname "$0")/../lib.sh"
indDone; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; sed -i "s/^);/    (E hold 0 1)\n);/" constant/indenterProperties; rm postProcessing/indentation/solid.xmf
cellIndentationFoam > log.run 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.run | head -8; tail -2 log.run; echo "rc=$rc"; ls postProcessing/indentation
echo "--- grids in the new solid.xmf vs steps in solid.h5:"; grep -c '<Grid Name' postProcessing/indentation/solid.xmf; h5ls postProcessing/indentation/solid.h5/steps | wc -l
