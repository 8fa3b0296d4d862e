#!/bin/bash
# y06: PARALLEL after SERIAL: a serial blast run to 2 ns, 0/p changed to 30 MPa, decomposePar (plain: decomposes the serial run's times too), mpirun -np 2 -parallel from 0: refused naming the times after the start? then -parallel -overwrite: runs, the old root and processor times moved aside? reconstructPar then gives the 30-MPa run?
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i 's/50000000/30000000/g; s/5e7/3e7/g' 0/p; splitY 4e-6; decomposePar > log.dec 2>&1 || tail -2 log.dec; echo "processor1 times: $(ls -d processor1/[0-9]* | tr '\n' ' ')"
run 120 mpirun -np 2 cellBlastFoam -parallel > log.p1 2>&1; fatal log.p1 4
run 120 mpirun -np 2 cellBlastFoam -parallel -overwrite > log.p2 2>&1; tail -1 log.p2; fatal log.p2 4
echo "root times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ') aside: $(ls -da .*overwrit* *overwrit* processor*/.*overwrit* 2>/dev/null | tr '\n' ' ')"
reconstructPar -latestTime > log.rec 2>&1; echo "reconstructPar -latestTime: rc $? $(fatal log.rec 2 | tr '\n' ' '); root 2e-09/p top row: $(grep -a -m1 '(1e-10' 2e-09/p)"
