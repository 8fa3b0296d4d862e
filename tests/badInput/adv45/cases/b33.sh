#!/bin/bash
# b33 (class 4, cellMeshDict odd numbers): cellDiameter, cellHeight, nucleusVolumeFraction, membraneThickness, membraneLayers, nucleusSize, contactRadius each set to 1e308, 1e-400, -0, a hex number, 4.9e-324, 1e400: each a FATAL IO ERROR naming the file, the entry and the range, nothing written (constant/cell.msh kept)?
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/cell.msh > ../m; cp system/cellMeshDict ../dict.orig
for k in cellDiameter cellHeight nucleusVolumeFraction membraneThickness membraneLayers nucleusSize contactRadius; do for v in 1e308 1e-400 -0 0x1p-20 4.9e-324 1e400; do cp ../dict.orig system/cellMeshDict; sete system/cellMeshDict $k $v
  timeout -s KILL 60 cellMesh > ../log.m 2>&1; echo "$k $v: rc=$? | $(grep -a -m1 -A2 'FATAL' ../log.m | grep -av '^ *$\|^-->\|From' | tr '\n' ' ' | cut -c1-200)"; done; done; echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk '{print $2}')"
