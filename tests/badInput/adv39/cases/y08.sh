#!/bin/bash
# y08: a 2-rank run to 1 ns, restarted to 2 ns (segments postProcessing/*/0 and */1e-09), then 0/p 30 MPa and mpirun -np 2 -parallel -overwrite from 0: only postProcessing/*/0 of the new run left (x18 on 2 ranks)?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 1e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.1 2>&1 || tail -2 log.1; latest; blastEnd 2e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.2 2>&1 || fatal log.2 3
for d in postProcessing/*; do echo "before $d: $(ls $d | tr '\n' ' ')"; done
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sed -i 's/50000000/30000000/g; s/5e7/3e7/g' 0/p
run 120 mpirun -np 2 cellBlastFoam -parallel -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 3
for d in postProcessing/*; do echo "after $d: $(ls $d | tr '\n' ' ')"; done
