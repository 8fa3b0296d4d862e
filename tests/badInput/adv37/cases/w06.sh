#!/bin/bash
# w06: blast: serial run to 2 ns, then decomposePar -latestTime (split at 4 um) and a 2-rank restart to 4 ns: continues and matches serial to 4 ns?
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r . ../ref; (cd ../ref && blastEnd 4e-9 1e-9 && latest && cellBlastFoam > log.ref 2>&1; echo "serial ref rc=$?")
splitY 4e-6; decomposePar -latestTime > log.dec 2>&1; echo "decomposePar rc=$?"; ls -a processor0/2e-09 | tr '\n' ' '; echo
latest; blastEnd 4e-9 1e-9; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 8; tail -1 log.r
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --tol 1e-9 --h5 2>&1 | tail -3
