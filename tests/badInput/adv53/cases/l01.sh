#!/bin/bash
# CASETIMEOUT=600
# l01 (new, class 1: a restart after reconstructPar, whose mesh the input record does not compare - inputRecord.H: "a
# serial restart of a reconstructed parallel run checks the dictionaries and schemes, not the mesh"): waterPulseWall run
# on 2 ranks to 2e-8, reconstructPar (the processor folders kept: the serial restart takes the reconstructed time as committed), then the whole case's constant/polyMesh (a) scaled by 1.01 along x
# (transformPoints), (b) replaced by a finer blockMesh of the same size (cells 2x): the serial restart to 4e-8;
# (c) control: constant/thermophysicalProperties changed (refused). Expected: (a), (b) refused naming the mesh (the
# fields of 2e-08 were computed on another mesh); a run on the scaled mesh ending rc 0 without a word = SILENT; (b) an
# OpenFOAM size error only = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
wp 2e-8; rm -rf [1-9]* postProcessing .*overwritten*; wpEnd 2e-8; wpDec; tryt 300 "(0) 2 ranks to 2e-8" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log)"
tryt 120 "(0) reconstructPar" reconstructPar -latestTime; echo "   times: $(ls -d [0-9]* | tr '\n' ' ') | 2e-08 holds $(ls -A 2e-08 | tr '\n' ' ')"
wpEnd 4e-8; cd $W; cp -a wp w0; again() { cd $W; rm -rf wp; cp -a w0 wp; cd wp; }
again; tryt 100 "(a0) transformPoints -scale (1.01 1 1)" transformPoints -scale '(1.01 1 1)'; tryt 300 "(a) serial restart to 4e-8 on the mesh scaled by 1.01 in x" rhoRiemannFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300) | times: $(ls -d [0-9]* | tr '\n' ' ')"
again; n=$(sed -n 's/^nCells *\([0-9]*\);.*/\1/p' system/blockMeshDict); sed -i "s/^nCells .*/nCells $((2*n));/" system/blockMeshDict; echo "   nCells $n -> $((2*n))"; blockMesh > log.blockMesh2 2>&1
tryt 300 "(b) serial restart to 4e-8 on a blockMesh of twice the cells" rhoRiemannFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
again; sete constant/thermophysicalProperties Gamma0 0.2 || sed -i '0,/Gamma0 *[^;]*;/s//Gamma0 0.2;/' constant/thermophysicalProperties; tryt 300 "(c) control: Gamma0 changed" rhoRiemannFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
