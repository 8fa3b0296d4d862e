#!/bin/bash
# i53 (class 1/SILENT, the extrapolated predictor on 2 ranks): xbd's prepared case split at y = 4 um, run on 2 ranks 0 ->
# 5e-9: against the serial xbd equal to round-off (closeTo: 1e-10 relative); then (b) that 2-rank run SIGKILLed after its
# 2nd commit and restarted on 2 ranks to 5e-9: bitwise the 2-rank straight run (sameSeries, solid.h5, processor0's last p).
. "$(dirname "$0")/../lib.sh"
xbd; S=$PWD; cp -a $S $W/p; cd $W/p; fresh; splitY 4e-6; decomposePar -force > log.decompose 2>&1 || tail -3 log.decompose; cp -a $W/p $W/pk
tryt 600 "2 ranks 0 -> 5e-9" mpirun -np 2 cellBlastFoam -parallel; closeTo $S
cd $W/pk; mpirun -np 2 cellBlastFoam -parallel > log.killed 2>&1 & k=$!; killAfter 2 $k; rm -f .runLock; latest; tryt 600 "(b) killed, restarted on 2 ranks" mpirun -np 2 cellBlastFoam -parallel; cont
sameSeries $W/p | sed 's/^/   /'; echo "   solid.h5: $(h5same solid/solid.h5 $W/p/solid/solid.h5) | processor0/5e-09/p: $(cmp -s processor0/5e-09/p $W/p/processor0/5e-09/p && echo same || echo DIFF)"
