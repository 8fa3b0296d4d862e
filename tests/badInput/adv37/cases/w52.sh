#!/bin/bash
# w52: cellMesh entries at their edges: nucleusVolumeFraction nan, membraneLayers 2.5, contactRadius -1e-6, cellHeight 0, membraneThickness inf, mode Full3D, mode 3D, nucleusShape '', nucleusSize 1e-300
. "$(dirname "$0")/../lib.sh"
ind; cp system/cellMeshDict ../orig; for e in "nucleusVolumeFraction nan" "membraneLayers 2.5" "contactRadius -1e-6" "cellHeight 0" "membraneThickness inf" "mode Full3D" "mode 3D" 'nucleusShape ""' "nucleusSize 1e-300"; do
  cp ../orig system/cellMeshDict; k=${e%% *}; v=${e#* }; if grep -q "^$k " system/cellMeshDict; then sed -i "s/^$k .*/$k $v;/" system/cellMeshDict; else echo "$k $v;" >> system/cellMeshDict; fi; try "$e" cellMesh; done
