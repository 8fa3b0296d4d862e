#!/bin/bash
# w03: blast, 2 ranks run to 2 ns, reconstructPar, re-decomposed elsewhere (split at y = 6 um instead of 4 um, decomposePar -force -latestTime), restarted to 4 ns on 2 ranks: continues and matches an uninterrupted run?
. "$(dirname "$0")/../lib.sh"
pblastDone; cp -r . ../ref; (cd ../ref && blastEnd 4e-9 1e-9 && mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ref 2>&1; echo "ref rc=$?")
reconstructPar > log.rec 2>&1; echo "reconstructPar rc=$?"; ls -a 2e-09 | tr '\n' ' '; echo
splitY 6e-6; decomposePar -force -latestTime > log.dec2 2>&1; echo "decomposePar rc=$?"; ls processor0 | tr '\n' ' '; echo
latest; blastEnd 4e-9 1e-9; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r; tail -1 log.r
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --tol 1e-9 --h5 2>&1 | tail -3
