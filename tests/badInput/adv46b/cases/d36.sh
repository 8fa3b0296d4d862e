#!/bin/bash
# d36 (class 4, cellMeshDict entries misspelt or odd, one at a time on the indentation case): membraneLayer 2 (misspelt, the real one has a default?), nucleusShape scaledcell, mode Axisymmetric, cellDiameter 0x1p-17, contactDepth 1e-400, membraneLayers 2.5, membraneLayers 1e308, cellHeight given twice: each refused naming the entry (and the closest valid keyword), cell.msh unchanged.
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/cell.msh > ../m; cp system/cellMeshDict ../d
for e in "membraneLayer 2" "nucleusShape scaledcell" "mode Axisymmetric" "cellDiameter 0x1p-17" "contactDepth 1e-400" "membraneLayers 2.5" "membraneLayers 1e308"; do cp ../d system/cellMeshDict; k=${e%% *}; if grep -q "^$k " system/cellMeshDict; then sete system/cellMeshDict $e; else echo "$e;" >> system/cellMeshDict; fi
  tryt 60 "$e" cellMesh; done; cp ../d system/cellMeshDict; echo "cellHeight 7.9e-6;" >> system/cellMeshDict; tryt 60 "cellHeight twice" cellMesh; echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"
