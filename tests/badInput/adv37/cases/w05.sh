#!/bin/bash
# w05: blast: 2-rank run finished, reconstructPar, then a SERIAL restart with latestTime to 4 ns: continues (or refused with a reason) and matches a serial run to 4 ns?
. "$(dirname "$0")/../lib.sh"
pblastDone; reconstructPar > log.rec 2>&1; echo "reconstructPar rc=$?"; ls -a 2e-09 2e-09/uniform | tr '\n' ' '; echo
cp -r ../blast ../ref; (cd ../ref && rm -rf processor* && rm -rf 1e-09 2e-09 solid postProcessing && blastEnd 4e-9 1e-9 && cellBlastFoam > log.ref 2>&1; echo "serial ref rc=$?")
latest; blastEnd 4e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 8; tail -1 log.r
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --tol 1e-9 --h5 2>&1 | tail -3
