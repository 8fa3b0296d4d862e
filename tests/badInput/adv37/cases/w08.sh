#!/bin/bash
# w08: blast 2 ranks run to 2 ns: processor1's latest time 2e-09 deleted (ranks disagree on latestTime), restart on 2 ranks to 3 ns
. "$(dirname "$0")/../lib.sh"
pblastDone; rm -rf processor1/2e-09; latest; blastEnd 3e-9 1e-9
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 8; tail -1 log.r; ls processor0 processor1 | tr '\n' ' '
