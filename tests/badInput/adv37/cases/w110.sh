#!/bin/bash
# w110: solidToFoam after the cell was re-meshed (cellMesh with other sizes) after the run: converts with solid.h5's own mesh, or mixes the new cell.msh with the old results?
. "$(dirname "$0")/../lib.sh"
blastDone; md5sum constant/cell.msh; try before solidToFoam solid/solid.h5; n0=$(head -20 constant/solid/polyMesh/points | grep -m1 '^[0-9]'); rm -rf constant/solid [0-9]*/solid system/solid
sed -i 's/0.5e-6\|5e-07/0.4e-6/g' system/cellMeshDict.allrun; cellMesh > log.cm 2>&1; echo "re-meshed rc=$?"; md5sum constant/cell.msh; try after solidToFoam solid/solid.h5; n1=$(head -20 constant/solid/polyMesh/points | grep -m1 '^[0-9]'); echo "points: $n0 before, $n1 after the re-mesh"
