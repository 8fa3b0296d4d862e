#!/bin/bash
# f15 (class 4, the 3D quarter decomposed for 2 ranks restarted on 3): q (2 ranks, 1e-09 2e-09), endTime 3e-9, mpirun -np 3 --oversubscribe cellBlastFoam -parallel: a clean error (processor directories 2, ranks 3), rc != 0, no signal, nothing changed.
. "$(dirname "$0")/../lib.sh"
q; qEnd 3e-9; sums > ../s0
tryt 120 "3 ranks on a 2-rank case" mpirun --oversubscribe -np 3 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"; grep -a -c 'signal\|Segmentation\|sigFpe\|stack' $W/try.log
