#!/bin/bash
# g08 (class 1, the ranks disagree) pbd (2 ranks, finished to 2e-09) with processor1/2e-09 deleted (rank 0 has 2e-09, rank 1 only 1e-09), restart latestTime to 3e-9 on 2 ranks: refused naming the ranks' different latest times, exit non-zero, within seconds; never a hang, never two ranks at two times.
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -rf processor1/2e-09; sums > ../s0
tryt 240 "processor1/2e-09 deleted" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"; ls processor0 processor1 | tr '\n' ' '; echo
