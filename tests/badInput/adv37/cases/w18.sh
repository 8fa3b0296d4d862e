#!/bin/bash
# w18: blast run to 2 ns, then the pulse's END in 0/p moved from 5 ns to 3 ns (rows not yet run; the file the Allrun's -pulse writes) and restart to 4 ns: the restart reads 2e-09/p (the old pulse): is the user's edit refused, said or silently ignored?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 4e-9 1e-9; sed -i 's/(5e-09 *50000000)/(3e-09 50000000)/; s/(5.1e-09 *0)/(3.1e-09 0)/' 0/p; grep -a -A7 "uniformValue" 0/p | tr -s ' \n' ' '; echo
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r; grep -a -i "0/p\|pulse" log.r | head -3; echo "4e-09/p pulse:"; grep -a -A8 "uniformValue" 4e-09/p | tr -s ' \n' ' '; echo
