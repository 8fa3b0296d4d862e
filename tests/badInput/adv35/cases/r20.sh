#!/bin/bash
# r20: blast: restart after cellMesh re-run with a finer cell (constant/cell.msh replaced)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd system/cellMeshDict nucleusSize 0.45e-6; cellMesh > log.cellMesh2 2>&1; echo "cellMesh rc=$?"
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head; echo "rc=${PIPESTATUS[0]}"
