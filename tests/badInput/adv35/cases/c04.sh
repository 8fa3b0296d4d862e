#!/bin/bash
# c04: cellMesh run while cellIndentationFoam runs (mesh replaced under a run)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.4; setd system/cellMeshDict nucleusSize 0.7e-6; cellMesh > log.cm 2>&1; echo "cellMesh rc=$?"; grep -A3 FATAL log.cm | head; wait $p; echo "run rc=$?"; tail -1 log.a
