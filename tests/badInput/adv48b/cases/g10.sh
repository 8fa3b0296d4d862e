#!/bin/bash
# g10 (class 1, the ranks' coupling states swapped) pbd with processor0/2e-09/uniform/fsiState and processor1/2e-09/uniform/fsiState swapped (each a valid state of the same time, of the other rank), restart on 2 ranks to 3e-9: refused naming the files, or (if the two are equal) continued exactly as B.
. "$(dirname "$0")/../lib.sh"
pbd; mv $W/pblast $W/B; cd $W/B; rs; tryt 240 "B clean restart" mpirun -np 2 cellBlastFoam -parallel
pbd; rs; cmp -s processor0/2e-09/uniform/fsiState processor1/2e-09/uniform/fsiState && echo "   (the two fsiState files are equal)" || echo "   (the two fsiState files differ)"
mv processor0/2e-09/uniform/fsiState ../f0; mv processor1/2e-09/uniform/fsiState processor0/2e-09/uniform/fsiState; mv ../f0 processor1/2e-09/uniform/fsiState; sums > ../s0
tryt 240 "fsiState swapped between ranks" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"; [ -d processor0/3e-09 ] && cmpRef $W/B 2>&1 | cut -c1-300
