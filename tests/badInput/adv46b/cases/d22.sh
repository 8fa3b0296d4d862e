#!/bin/bash
# d22 (class 2+4, solidToFoam -region named like a folder OpenFOAM reads in a time directory: -region polyMesh and -region uniform on the finished preview): refused (a region named polyMesh/uniform writes <time>/polyMesh or <time>/uniform); else no file of the run changed, and a restart afterwards not misled (no moved mesh read, fsiState intact).
. "$(dirname "$0")/../lib.sh"
for r in polyMesh uniform; do cd $W; rm -rf blast; bd; rs; sums > ../s0; tryt 120 "solidToFoam -region $r" solidToFoam -region $r solid/solid.h5; echo "   changed/new: $(changed ../s0 | cut -c1-300)"
  tryt 240 "   restart after it" cellBlastFoam; cont; after; done
