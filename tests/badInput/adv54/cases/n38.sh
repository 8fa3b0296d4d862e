#!/bin/bash
# CASETIMEOUT=900
# n38 (new, class 1: the moving-mesh blast across decompositions - a regression check for a restart that compares the
# whole mesh): (a) pbd (2 ranks, finished at 2e-9, the band mesh moved) reconstructed (reconstructPar), the serial
# restart to 3e-9; (b) bd (serial, finished) decomposed (decomposePar -latestTime, simple 1 2 1 ... as pbd's split: the
# corpus' splitY and decomposePar) and the 2-rank restart to 3e-9; (c) pbd's 2-rank restart to 3e-9 (control).
# Expected: each runs (the same problem on another decomposition); a refusal of an unchanged mesh = a regression.
. "$(dirname "$0")/../lib.sh"
pbd; cp -a . $W/p0; rs; rm -f .runLock; tryt 600 "(c) pbd's 2-rank restart to 3e-9" mpirun -np 2 cellBlastFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; rm -rf pblast; cp -a p0 pblast; cd pblast; tryt 300 "(a0) reconstructPar" reconstructPar; rs; rm -f .runLock; tryt 600 "(a) the serial restart of the reconstructed run" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
cd $W; bd; cp $W/p0/system/decomposeParDict system/ 2>/dev/null; splitY 4e-6 > /dev/null 2>&1; tryt 300 "(b0) decomposePar -latestTime" decomposePar -latestTime; rs; rm -f .runLock; tryt 600 "(b) the 2-rank restart of the serial run" mpirun -np 2 cellBlastFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"
