#!/bin/bash
# w58: cellMesh keyword mistakes: nucleusSzie (typo at the top), nearSzie in fluid, mode given twice
. "$(dirname "$0")/../lib.sh"
blast; cp system/cellMeshDict ../orig; sed -i 's/^nucleusSize/nucleusSzie/' system/cellMeshDict; grep -q nucleusSzie system/cellMeshDict || echo "nucleusSzie 0.5e-6;" >> system/cellMeshDict; try typo cellMesh
cp ../orig system/cellMeshDict; sed -i 's/nearSize/nearSzie/' system/cellMeshDict; grep -q nearSzie system/cellMeshDict && try fluidTypo cellMesh
cp ../orig system/cellMeshDict; echo "mode axisymmetric;" >> system/cellMeshDict; echo "mode full3D;" >> system/cellMeshDict; try twice cellMesh
