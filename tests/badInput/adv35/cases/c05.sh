#!/bin/bash
# c05: solidToFoam while cellIndentationFoam writes solid.h5
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; setd system/controlDict fieldWriteInterval 0.05
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.8; solidToFoam postProcessing/indentation/solid.h5 > log.s 2>&1; echo "solidToFoam rc=$?"; grep -A3 "FATAL\|rror" log.s | head -5; tail -2 log.s; wait $p; echo "run rc=$?"
