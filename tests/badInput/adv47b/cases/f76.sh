#!/bin/bash
# f76 (class 1/5, one rank's commit marker missing): q (2 ranks, 1e-09 2e-09) with processor1/2e-09/.writeCommitted removed (rank 1's write of 2e-09 looks interrupted, rank 0's is whole), restart latestTime to 3e-9 on 2 ranks: both ranks continue from 1e-09 (the last time both committed) or the run is refused naming the ranks' times; never a hang (ranks at different times), never rank 0 at 2e-09 and rank 1 at 1e-09.
. "$(dirname "$0")/../lib.sh"
q; latest; qEnd 3e-9; rm processor1/2e-09/.writeCommitted; sums > ../s0
tryt 200 "processor1/2e-09 without its marker" mpirun -np 2 cellBlastFoam -parallel; cont; grep -a -m3 'incomplete\|Start time\|FATAL' $W/try.log | cut -c1-200
echo "   rank0: $(ls -d processor0/[0-9]* processor0/*incomplete* 2>/dev/null | tr '\n' ' ') rank1: $(ls -d processor1/[0-9]* processor1/*incomplete* 2>/dev/null | tr '\n' ' ')"; echo "   solid.h5 $(h5steps solid/solid.h5) steps"
