#!/bin/bash
# g09 (class 1, a rank's own uniform/time) pbd with processor1/2e-09/uniform/time's value changed to 2.5e-09 (rank 0's kept), restart latestTime to 3e-9 on 2 ranks: refused naming processor1/2e-09/uniform/time, or continued exactly as the clean 2-rank restart B; never a hang.
. "$(dirname "$0")/../lib.sh"
pbd; mv $W/pblast $W/B; cd $W/B; rs; tryt 240 "B clean restart" mpirun -np 2 cellBlastFoam -parallel
pbd; rs; sed -i 's/^\(value *\)[-+0-9.eE]* *;/\12.5e-09;/' processor1/2e-09/uniform/time; grep -a '^value' processor1/2e-09/uniform/time; sums > ../s0
tryt 240 "rank 1 uniform/time 2.5e-09" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"; ls processor0 | tr '\n' ' '; echo; [ -d processor0/3e-09 ] && { cmpRef $W/B 2>&1 | cut -c1-300; for f in p rho; do cmp -s processor1/3e-09/$f $W/B/processor1/3e-09/$f && echo "   processor1/3e-09/$f same as B" || echo "   processor1/3e-09/$f DIFF from B"; done; }
