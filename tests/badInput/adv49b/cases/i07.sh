#!/bin/bash
# i07 (class 1, a restart continued with the other meshType): (a) the unstructured preview finished at 2e-9 (bd): meshType
# structured set in its cellMeshDict and cellMesh run again (it replaces constant/cell.msh, documented), then the restart
# (latestTime, to 3e-9): refused naming the solid mesh (constant/cell.msh changed), nothing written. (b) the structured
# preview finished at 5e-9 (sbd) remeshed unstructured, then its restart: refused likewise. Never "Continuing" with a solid
# whose mesh is not the one of solid.h5 and the uniform/solidState.
. "$(dirname "$0")/../lib.sh"
bd; rs; echo 'meshType structured;' >> system/cellMeshDict; cm; sums > ../s0
tryt 300 "(a) unstructured run, restart on a structured cell" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
sbd; rs6; sed -i '/meshType/d' system/cellMeshDict.allrun; cm; sums > ../s1
tryt 300 "(b) structured run, restart on an unstructured cell" cellBlastFoam; cont; echo "   changed: $(changed ../s1)"; after
