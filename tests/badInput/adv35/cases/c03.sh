#!/bin/bash
# c03: two cellIndentationFoam at once, the second through a symlinked path to the same case
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; ln -s "$W/ind" "$W/link"
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.4; (cd "$W/link" && cellIndentationFoam > log.b 2>&1); echo "second rc=$?"; grep -A4 FATAL log.b | head -6; wait $p; echo "first rc=$?"; tail -1 log.a
