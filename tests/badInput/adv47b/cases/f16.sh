#!/bin/bash
# f16 (class 2/4, the 3D quarter's parallel results, restarted on 1 rank): (a) mpirun -np 1 cellBlastFoam -parallel: a clean error; (b) serial cellBlastFoam (startFrom latestTime: the case root holds no time but 0, the results are in processor*, solid/ and postProcessing/ in the root): refused (a new start over results), solid.h5 and the logs unchanged; never a serial run writing over the parallel run's solid.h5.
. "$(dirname "$0")/../lib.sh"
q; qEnd 3e-9; latest; sums > ../s0
tryt 120 "(a) -np 1 -parallel" mpirun -np 1 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"
tryt 240 "(b) serial restart of a parallel case" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
