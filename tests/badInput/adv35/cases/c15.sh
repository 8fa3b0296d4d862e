#!/bin/bash
# c15: cellMesh twice at once in one case (no solver)
. "$(dirname "$0")/../lib.sh"
ind; setd system/cellMeshDict nucleusSize 0.3e-6
cellMesh > log.a 2>&1 & p=$!; sleep 0.2; cellMesh > log.b 2>&1; echo "second rc=$?"; grep -A2 FATAL log.b | head -3; wait $p; echo "first rc=$?"; tail -1 log.a; ls -la constant; head -3 constant/cell.msh
