#!/bin/bash
# w05: blast: 2 ranks to 7 ns, reconstructPar, then a SERIAL restart with latestTime to 14 ns: continues (or refused with a reason); equal to the uninterrupted serial run to 14 ns within 1e-9?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 14e-9 7e-9; cellBlastFoam > log.ref 2>&1; echo "serial reference rc=$?"; cd ..; mv blast ref; pblast; blastEnd 7e-9 7e-9; mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1; echo "2 ranks to 7 ns rc=$?"
reconstructPar > log.rec 2>&1; echo "reconstructPar rc=$?"; ls -a 7e-09 7e-09/uniform | tr '\n' ' '; echo
latest; blastEnd 14e-9 7e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 8; tail -1 log.r; grep -a -m1 "Continuing\|restarted" log.r | cut -c1-200
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --tol 1e-9 --h5 2>&1 | cut -c1-300 | tail -5
