#!/bin/bash
# c14: cellIndentationFoam running while a second one runs with -overwrite in the same case
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.5; cellIndentationFoam -overwrite > log.b 2>&1; echo "second rc=$?"; grep -A2 FATAL log.b | head -3; wait $p; echo "first rc=$?"; tail -1 log.a; tail -1 postProcessing/indentation/force.dat
