#!/bin/bash
# g12 (class 1, a rank's uniform/ folder gone) pbd with processor1/2e-09/uniform deleted whole (rank 0's kept), restart on 2 ranks to 3e-9: refused naming processor1/2e-09/uniform's files and the marker, exit non-zero, no hang, nothing written.
. "$(dirname "$0")/../lib.sh"
pbd; rs; ls processor1/2e-09/uniform | tr '\n' ' '; echo; rm -rf processor1/2e-09/uniform; sums > ../s0
tryt 240 "processor1/2e-09/uniform deleted" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"
