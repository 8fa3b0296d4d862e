#!/bin/bash
# w38: ind killed at 2 s, cell.msh re-meshed (cellMesh with nucleusSize x 0.8), restart: refused naming the mesh?
. "$(dirname "$0")/../lib.sh"
indKilled 2; v=$(foamDictionary -entry nucleusSize -value system/cellMeshDict); n=$(python3 -c "print($v*0.8)"); sed -i "s/^nucleusSize .*/nucleusSize $n;/" system/cellMeshDict; run 60 cellMesh > log.cm 2>&1; fatal log.cm 3
run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
