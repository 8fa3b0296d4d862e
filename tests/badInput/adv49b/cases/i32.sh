#!/bin/bash
# i32 (class 4/HANG, rank counts that do not fit the case): pbd (processor0, processor1) restarted to 3e-9 with (a) mpirun -np 3
# -parallel, (b) mpirun -np 2 -parallel after processor1 renamed processor2 (ranks 0 and 2 exist, 1 missing), (c) mpirun -np 2
# -parallel in the case after `reconstructPar` and the processor folders removed; each refused within seconds naming the
# ranks and the processor folders (decomposePar), exit non-zero, nothing changed, never a hang (120 s).
. "$(dirname "$0")/../lib.sh"
pbd; rs; sums > ../s0; tryt 120 "(a) -np 3" mpirun -np 3 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"; rm -f .runLock
mv processor1 processor2; sums > ../s0; tryt 120 "(b) processor1 renamed processor2" mpirun -np 2 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"; mv processor2 processor1; rm -f .runLock
reconstructPar > log.reconstruct 2>&1; mkdir ../aside; mv processor* ../aside/; sums > ../s0; tryt 120 "(c) no processor folders" mpirun -np 2 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"
