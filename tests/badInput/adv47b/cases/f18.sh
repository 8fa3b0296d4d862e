#!/bin/bash
# f18 (class 1, the 3D quarter's ranks at different times): (a) processor0/2e-09 removed by the user (rank 1 keeps 2e-09), restart latestTime on 2 ranks: refused naming the ranks' times (or both continue from 1e-09 consistently); never a hang or ranks starting at different times. (b) processor1 replaced by that of another run of the same case continued to 3e-09 (B): refused, or both start at 2e-09; never rank 1 at 3e-09 and rank 0 at 2e-09.
. "$(dirname "$0")/../lib.sh"
q; mv $W/q $W/B; cd $W/B; latest; qEnd 3e-9; tryt 280 "B: restart to 3e-9" mpirun -np 2 cellBlastFoam -parallel
q; latest; qEnd 4e-9; rm -rf processor0/2e-09; sums > ../s0
tryt 200 "(a) processor0/2e-09 removed" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"; grep -a 'Starting time loop\|Time = ' $W/try.log | head -2
cd $W; rm -rf q; q; latest; qEnd 4e-9; rm -rf processor1; cp -a $W/B/processor1 .; sums > ../s0
tryt 200 "(b) processor1 of B (3e-09)" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"
