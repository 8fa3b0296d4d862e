#!/bin/bash
# k15 (class 3, cellMesh while cellBlastFoam runs in the same case): bd restarted to 30e-9 in the background; once its lock exists, the cell's sizes changed in cellMeshDict.allrun and cellMesh run in the case. Expected: cellMesh refused naming the running run (one run per case), cell.msh unchanged; or, if it meshes, the running run's results are not later taken with the new mesh: the restart after it refuses naming constant/cell.msh. Then solidToFoam on the case (it reads cell.msh and solid.h5).
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 30e-9 1e-9; msh > $W/m0; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 1; echo "   lock: $(lockOf | cut -c1-120)"
mset nucleusSize 0.35e-6; mset cytoplasmSize 0.35e-6; tryt 200 "cellMesh while the run goes" cellMesh; echo "   cell.msh: $(cat $W/m0) -> $(msh); run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
sleep 3; kill -KILL $p; wait $p 2>/dev/null; echo "   run killed at: $(ls -d [0-9]* | tr '\n' ' ')"; rm -f .runLock
blastEnd 31e-9 1e-9; tryt 200 "restart after cellMesh" cellBlastFoam; cont; after
tryt 300 "solidToFoam solid/solid.h5" solidToFoam solid/solid.h5; ls -d */solid 2>/dev/null | wc -l
