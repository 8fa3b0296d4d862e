#!/bin/bash
# w19: blast run to 2 ns: the pulse table inside 2e-09/p edited (50 -> 30 MPa over rows already run), restart: refused by the digest; with -acceptEdited: said in the log that the pulse of the run changed?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/50000000/30000000/g' 2e-09/p
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4
run 120 cellBlastFoam -acceptEdited > log.r2 2>&1; grep -a -i "edited\|accept" log.r2 | head -3 | cut -c1-300; tail -1 log.r2
