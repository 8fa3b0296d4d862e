#!/bin/bash
# q12: `cellBlastFoam -postProcess` on 2 ranks with -func fluidProbes and a plain serial `cellBlastFoam -postProcess` in a decomposed case (processor* dirs, no serial times beyond 0): logs kept? then a 2-rank restart continues?
. "$(dirname "$0")/../lib.sh"
pblastDone; sums > ../before
run 120 mpirun -np 2 cellBlastFoam -parallel -postProcess -func fluidProbes > log.pp 2>&1 | tail -1; fatal log.pp 3; nochange ../before
tryf "serial -postProcess in the decomposed case" cellBlastFoam -postProcess; nochange ../before
latest; blastEnd 3e-9 1e-9; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1 | tail -1; fatal log.r 3; echo "processor1: $(ls -d processor1/[1-9]* | tr '\n' ' ')"
