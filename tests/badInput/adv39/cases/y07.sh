#!/bin/bash
# y07: SERIAL after PARALLEL, not reconstructed: a 2-rank run to 2 ns (50 MPa); 0/p to 30 MPa; serial cellBlastFoam from 0: refused naming processor*/ times? then -overwrite: runs; processor*/ times moved aside? then a 2-rank restart from latestTime: continues which run?
. "$(dirname "$0")/../lib.sh"
pblastDone; sed -i 's/50000000/30000000/g; s/5e7/3e7/g' 0/p
run 120 cellBlastFoam > log.s1 2>&1; fatal log.s1 4
run 120 cellBlastFoam -overwrite > log.s2 2>&1; tail -1 log.s2; fatal log.s2 3
echo "root times: $(ls -d [1-9]* | tr '\n' ' '); processor1: $(ls -a processor1 | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; run 120 mpirun -np 2 cellBlastFoam -parallel > log.p3 2>&1; echo "2-rank restart from latestTime: $(tail -1 log.p3 | cut -c1-100) | $(fatal log.p3 3 | tr '\n' ' ')"; echo "processor1 times now: $(ls -d processor1/[0-9]* | tr '\n' ' ')"
