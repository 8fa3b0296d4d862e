#!/bin/bash
# c01: two cellIndentationFoam at once in one case
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.4; cellIndentationFoam > log.b 2>&1; echo "second rc=$?"; grep -A4 FATAL log.b | head -6; wait $p; echo "first rc=$?"; tail -1 log.a
