#!/bin/bash
# w21: blast run to 2 ns, then cellMesh re-run with -cell 0.4 um (cellMeshDict.allrun) so constant/cell.msh changes, restart: refused naming the mesh?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; md5sum constant/cell.msh; cat system/cellMeshDict.allrun; sed -i 's/0.5e-06\|5e-07\|0.5e-6/0.4e-6/g' system/cellMeshDict.allrun; cat system/cellMeshDict.allrun
run 120 cellMesh > log.cm 2>&1; fatal log.cm 4; md5sum constant/cell.msh
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
