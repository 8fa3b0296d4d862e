#!/bin/bash
# w107: wrong files and sets: solidProperties file pointing at constant/polyMesh/points (not a gmsh file) and at a missing file; indenterProperties contactPatch 'axis' (a node set on the axis, no surface) and 'nucleus' (a volume region)
. "$(dirname "$0")/../lib.sh"
blast; f=constant/solidProperties; cp $f ../sp; sed -i 's|file        "constant/cell.msh";|file "constant/polyMesh/points";|' $f; try "file polyMesh/points" cellBlastFoam; rm -rf solid postProcessing [1-9]*
cp ../sp $f; sed -i 's|file        "constant/cell.msh";|file "constant/nothere.msh";|' $f; try "file missing" cellBlastFoam; cd ..
ind; for s in axis nucleus; do setd constant/indenterProperties contactPatch $s; try "contactPatch $s" cellIndentationFoam; rm -rf postProcessing; done
