#!/bin/bash
# g11 (class 1, a rank's moved mesh of another time) pbd with processor1/2e-09/polyMesh/points replaced by processor1/1e-09/polyMesh/points, restart on 2 ranks to 3e-9: refused naming processor1/2e-09/polyMesh/points, nothing written, no hang.
. "$(dirname "$0")/../lib.sh"
pbd; rs; ls processor1/2e-09/polyMesh 2>&1 | tr '\n' ' '; echo; cp processor1/1e-09/polyMesh/points processor1/2e-09/polyMesh/points; sums > ../s0
tryt 240 "rank 1 points of 1e-09" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"
