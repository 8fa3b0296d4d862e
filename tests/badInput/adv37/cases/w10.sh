#!/bin/bash
# w10: blast 2 ranks run to 2 ns: processor0 and processor1 renamed into each other, restart on 2 ranks
. "$(dirname "$0")/../lib.sh"
pblastDone; mv processor0 p0; mv processor1 processor0; mv p0 processor1; latest; blastEnd 3e-9 1e-9
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 8; tail -1 log.r
