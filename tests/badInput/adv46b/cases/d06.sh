#!/bin/bash
# d06 (class 1, blast restart after cellMesh re-run with another cell size: cellMeshDict.allrun membraneSize 4e-07 -> 3.5e-07, cellMesh, restart): refused naming constant/cell.msh (the solid mesh); never continued on another mesh.
. "$(dirname "$0")/../lib.sh"
bd; rs; md5sum constant/cell.msh > ../m; sed -i "s/^membraneSize .*/membraneSize 3.5e-07;/" system/cellMeshDict.allrun
tryt 120 "cellMesh with membraneSize 3.5e-07" cellMesh; echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"
tryt 240 "restart on the new mesh" cellBlastFoam; cont; after
