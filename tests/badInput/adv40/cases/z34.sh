#!/bin/bash
# z34: z01 on 2 ranks: a finished 2-rank blast case, `mpirun -np 2 cellBlastFoam -parallel -postProcess`, then a 2-rank restart to 3 ns: the logs kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; sums > ../before
run 120 mpirun -np 2 cellBlastFoam -parallel -postProcess > log.pp 2>&1 | tail -1; echo "changed: $(changed ../before)"
latest; blastEnd 3e-9 1e-9; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1 | tail -1; fatal log.r 3; echo "processor1: $(ls -d processor1/[1-9]* | tr '\n' ' ')"
