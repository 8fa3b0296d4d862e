#!/bin/bash
# i52 (class 1, the structured run's restart after edits cellMesh does not use): sbd (structured, 5e-9) with contactRadius 3e-6
# and contactSize 0.3e-6 set in cellMeshDict (unused by the structured section) and cellMesh run again: if cell.msh is
# byte-identical the restart to 6e-9 continues (exit 0) and equals the plain restart's results; if cell.msh differs it is
# refused naming constant/cell.msh. Then (b) membraneSize changed and cellMesh run: refused naming the solid mesh.
. "$(dirname "$0")/../lib.sh"
sbd; cd $W; cp -a sblast ref; cd ref; rs6; cellBlastFoam > log.r 2>&1 || echo "ref failed"; cd $W/sblast; rs6; md5sum constant/cell.msh > ../m0
mset contactRadius 3e-6; mset contactSize 0.3e-6; cm; echo "   cell.msh: $(md5sum -c ../m0 2>&1 | tail -1)"
tryt 300 "(a) restart after an unused contact edit" cellBlastFoam; cont; [ -d 6e-09 ] && cmp6 $W/ref; rm -rf 6e-09; echo
mset membraneSize 0.3e-6; cm; sums > ../s0; tryt 300 "(b) restart after membraneSize 0.3e-6 remeshed" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
