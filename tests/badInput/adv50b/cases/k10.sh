#!/bin/bash
# k10 (class 4/silent, oGrid with the tetrahedral water): (a) cellMeshDict fluid type tetrahedra with hexCoeffs { oGrid orthogonal; } (the guide: hexCoeffs "type hex only (ignored with tetrahedra)"); (b) the quarter's Allrun -tet -oGrid orthogonal -noRun (the Allrun header lists -dz, -lateral, -margin as not used with -tet; -oGrid not). Expected: the option/entry refused as not applying to tetrahedra, or the log saying it is ignored; never accepted without a word while the mesh is not orthogonalised.
. "$(dirname "$0")/../lib.sh"
qm "type tetrahedra;" "oGrid orthogonal;"; cm; echo "   log on oGrid: $(grep -a -i -m2 'ogrid\|orthogonal\|ignored' $W/try.log | cut -c1-200 | tr '\n' '|')"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/qt; cd $W/qt; tryt 400 "(b) Allrun -tet -oGrid orthogonal -noRun" ./Allrun -box 30e-6 -h 1e-6 -far 5e-6 -cell 1.4e-6 -tet -oGrid orthogonal -noRun -noPlots
echo "   Allrun log on oGrid: $(grep -a -i -m2 'ogrid\|orthogonal\|ignored\|not used' $W/try.log log.cellMesh 2>/dev/null | cut -c1-200 | tr '\n' '|')"; cat system/cellMeshDict.allrun 2>/dev/null | sed 's/^/   allrun: /'
