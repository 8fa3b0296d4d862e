#!/bin/bash
# a06 (class 2, fix19y's rule at ANOTHER start time): a blast finished to 2 ns; time 2e-09 removed (foamListTimes -rm -time 2e-09), so that latestTime is 1e-09; the user's own postProcessing/fsi/1e-09/coupling.dat ("a06 my coupling table", no header) and fluidProbes/1e-09/p; restart to 3 ns from 1e-09: refused naming them, or written over?
. "$(dirname "$0")/../lib.sh"
blastDone; foamListTimes -rm -time 2e-09 > /dev/null 2>&1; echo "   times $(ls -d [1-9]* | tr '\n' ' '); fsi: $(ls postProcessing/fsi | tr '\n' ' ')"
P=postProcessing; mkdir -p $P/fsi/1e-09 $P/fluidProbes/1e-09; echo "a06 my coupling table" > $P/fsi/1e-09/coupling.dat; echo "a06 my p notes" > $P/fluidProbes/1e-09/p
latest; blastEnd 3e-9 1e-9; sums > ../s; tryf "restart 1 -> 3 ns" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kept "a06 my coupling table" "a06 my p notes"; nochange ../s
