#!/bin/bash
# f10 (class 1, a mesh and the dictionary that made it): after the finished preview, cellMesh run again with membraneSize 4e-7 -> 3e-7 in system/cellMeshDict.allrun (cellMesh replaces constant/cell.msh), then restart latestTime: refused naming constant/cell.msh (the solid mesh differs), nothing written.
. "$(dirname "$0")/../lib.sh"
bd; rs; sed -i 's/^membraneSize .*/membraneSize 3e-07;/' system/cellMeshDict.allrun; grep -c 'membraneSize 3e-07' system/cellMeshDict.allrun; md5sum constant/cell.msh > ../m0
tryt 120 "cellMesh again" cellMesh; echo "   cell.msh $(md5sum -c ../m0 2>/dev/null | grep -q OK && echo same || echo CHANGED)"; sums > ../s0
tryt 240 "restart after the new cell.msh" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
