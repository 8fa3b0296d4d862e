#!/bin/bash
# f73 (class 4, -parallel without mpirun and mpirun on the serial solver): (a) cellBlastFoam -parallel in the decomposed quarter (q) started directly, (b) rhoRiemannFoam -parallel in the sod case, (c) mpirun -np 2 cellIndentationFoam -parallel in the smoke indentation: each a clean error naming -parallel (rc != 0, no stack trace, no signal), nothing changed (as f16 (a)).
. "$(dirname "$0")/../lib.sh"
q; qEnd 3e-9; sums > ../s0; tryt 60 "(a) cellBlastFoam -parallel without mpirun" cellBlastFoam -parallel; grep -a -c 'printStack\|Aborted\|signal' $W/try.log; echo "   changed: $(changed ../s0)"
sod; tryt 60 "(b) rhoRiemannFoam -parallel without mpirun" rhoRiemannFoam -parallel; grep -a -c 'printStack\|Aborted\|signal' $W/try.log
ind; tryt 60 "(c) mpirun -np 2 cellIndentationFoam -parallel" mpirun -np 2 cellIndentationFoam -parallel; grep -a -c 'printStack\|Aborted\|signal' $W/try.log; ls postProcessing/indentation 2>/dev/null | tr '\n' ' '; echo
