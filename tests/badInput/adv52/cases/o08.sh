#!/bin/bash
# CASETIMEOUT=600
# o08 (fix19h's collated decomposition named, adv51 m07 (k), varied: the other solver, the other collated handler, a mixed
# case): (a) the sod tube (rhoRiemannFoam) decomposed `decomposePar -fileHandler collated` (2 ranks, simple), run with
# `mpirun -np 2 rhoRiemannFoam -parallel`; (b) the 2-rank preview (pblast) decomposed with -fileHandler hostCollated
# (processors2_0-1?), cellBlastFoam -parallel; (c) pblast decomposed twice: uncollated (processor0/1) and collated
# (processors2): runs on processor0/1 (and says processors2 is not read) or refuses; (d) (a) with `-fileHandler collated`
# given to the solver too. Each: refused rc 1 naming the collated folder and the uncollated handler, or runs right; never
# "decompose the case first" for a decomposed case, never a signal or hang.
. "$(dirname "$0")/../lib.sh"
st() { echo "   folders: $(ls -d processor* 2>/dev/null | tr '\n' ' ') | said: $(grep -a -m3 -i 'collated\|processor\|decompos' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-400)"; echo "   sig: $(sig)"; }
sod; printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n' > system/decomposeParDict
tryt 120 "(a0) decomposePar -fileHandler collated (sod)" decomposePar -fileHandler collated; st
tryt 120 "(a) mpirun -np 2 rhoRiemannFoam -parallel" mpirun -np 2 rhoRiemannFoam -parallel; st
tryt 120 "(d) mpirun -np 2 rhoRiemannFoam -parallel -fileHandler collated" mpirun -np 2 rhoRiemannFoam -parallel -fileHandler collated; st
cd $W; rm -rf sod; pblast; rm -rf processor*; tryt 120 "(b0) decomposePar -fileHandler hostCollated (preview)" decomposePar -fileHandler hostCollated; st
short; tryt 120 "(b) mpirun -np 2 cellBlastFoam -parallel" mpirun -np 2 cellBlastFoam -parallel; st
rm -rf processor*; decomposePar > log.dec1 2>&1; tryt 120 "(c0) and then -fileHandler collated too" decomposePar -fileHandler collated; st
tryt 120 "(c) mpirun -np 2 cellBlastFoam -parallel (processor0/1 and processors2)" mpirun -np 2 cellBlastFoam -parallel; st; echo "   End: $(grep -a -c '^End' $W/try.log) | processor0 times: $(ls -d processor0/[0-9]* | tr '\n' ' ')"
