#!/bin/bash
# x16: blast 2 ranks to 2 ns, reconstructPar (root times 1e-09, 2e-09 unmarked), then a SERIAL -overwrite from 0 with 30 MPa: the root's reconstructed times replaced; the processor*/ times of the 50-MPa run left beside the 30-MPa root run? said? a later reconstructPar then mixes?
. "$(dirname "$0")/../lib.sh"
pblastDone; reconstructPar > log.rec 2>&1 || tail -2 log.rec; sed -i 's/50000000/30000000/g' 0/p
run 120 cellBlastFoam -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 6; grep -a -i "processor" log.o | head -3 | cut -c1-250
echo "root 2e-09/p top: $(grep -a "(1e-10" 2e-09/p)"; echo "processor1 times: $(ls -d processor1/[1-9]* | tr '\n' ' ')"
reconstructPar > log.rec2 2>&1; echo "reconstructPar again: exit $?; root 2e-09/p top now: $(grep -a "(1e-10" 2e-09/p)"
latest; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 4
echo "processor1/2e-09/p pulse row: $(grep -a '(1e-10' processor1/2e-09/p)"
