#!/bin/bash
# y13: a 2-rank run to 2 ns; processor1/2e-09/.writeCommitted emptied (ONE rank's marker: a power loss on one node); mpirun -np 2 restart from latestTime to 3 ns: both ranks from the same time (moved aside on both / refused), or ranks from different times (hang, crash, mixed)?
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; : > processor1/2e-09/.writeCommitted
run 150 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r | cut -c1-150; fatal log.r 4; grep -a -m3 -i "aside\|Starting time\|from time" log.r | cut -c1-200
echo "processor0: $(ls -a processor0 | tr '\n' ' ')"; echo "processor1: $(ls -a processor1 | tr '\n' ' ')"
