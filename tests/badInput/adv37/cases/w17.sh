#!/bin/bash
# w17: blast run to 2 ns, then constant/dynamicMeshDict switched to dynamicMotionSolverFvMesh + displacementLaplacian (the mesh motion), restart to 3 ns: refused or said?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9
cat >> constant/dynamicMeshDict <<'D'
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
solver          displacementLaplacian;
displacementLaplacianCoeffs { diffusivity uniform; }
D
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r
