#!/bin/bash
# d08 (class 1, indentation restart after cellMesh re-run with contactSize 0.3e-6 -> 0.25e-6): refused naming the mesh (entry mesh/file or constant/cell.msh), nothing changed.
. "$(dirname "$0")/../lib.sh"
ik; sums > ../s0; sed -i "s/^contactSize .*/contactSize           0.25e-6;/" system/cellMeshDict
tryt 120 "cellMesh contactSize 0.25e-6" cellMesh
tryt 200 "restart on the new mesh" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after
