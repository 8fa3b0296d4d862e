#!/bin/bash
# x12: blast finished to 2 ns: -overwrite from the FIRST time (startTime 0, unchanged controlDict) with another amplitude (30 MPa): runs, leaves no .overwritten, no 50-MPa time, no mixed logs; the restart to 3 ns continues it?
. "$(dirname "$0")/../lib.sh"
blastDone; sed -i 's/50000000/30000000/g' 0/p; run 120 cellBlastFoam -overwrite > log.o 2>&1; tail -1 log.o; fatal log.o 3
echo "left aside: $(find . -name '.*overwritten*' | tr '\n' ' ')"; grep -a -c "" postProcessing/fsi/0/coupling.dat; echo "2e-09/p pulse row: $(grep -a "(1e-10" 2e-09/p)"
latest; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 3
