#!/bin/bash
# CASETIMEOUT=900
# n30 (new, class 1: adv53 l01's class with a PARALLEL restart - the reconstructed mesh changed, then decomposed again; and
# a re-decomposition of the same mesh): waterPulseWall on 2 ranks to 2e-8, reconstructPar -latestTime; (a)
# transformPoints -scale '(1.01 1 1)' on the reconstructed mesh, decomposePar -force, the 2-rank restart to 4e-8; (b) the
# same mesh decomposed again by scotch (decomposePar -force), the 2-rank restart; (c) the processor*/ folders' meshes
# scaled (transformPoints -scale in each processor folder: -case processorN), the 2-rank restart. Expected: (a), (c)
# refused naming the mesh; (b) runs (the same problem); a restart on the scaled mesh = SILENT.
. "$(dirname "$0")/../lib.sh"
wp 2e-8; rm -rf [1-9]* postProcessing .*overwritten*; wpEnd 2e-8; wpDec; tryt 300 "(0) 2 ranks to 2e-8" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log)"
tryt 120 "(0) reconstructPar" reconstructPar -latestTime; wpEnd 4e-8; cd $W; cp -a wp w0; again() { cd $W; rm -rf wp; cp -a w0 wp; cd wp; }
again; tryt 100 "(a0) transformPoints -scale (1.01 1 1)" transformPoints -scale '(1.01 1 1)'; tryt 200 "(a0) decomposePar -force" decomposePar -force -latestTime
tryt 300 "(a) 2-rank restart on the scaled, re-decomposed mesh" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
again; sed -i 's/^method .*/method scotch;/' system/decomposeParDict; tryt 200 "(b0) decomposePar -force (scotch)" decomposePar -force -latestTime; tryt 300 "(b) 2-rank restart, the same mesh decomposed by scotch" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
again; for r in 0 1; do tryt 100 "(c0) transformPoints in processor$r" transformPoints -case processor$r -scale '(1.01 1 1)'; done; tryt 300 "(c) 2-rank restart on the ranks' meshes scaled" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
