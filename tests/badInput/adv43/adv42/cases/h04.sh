#!/bin/bash
# h04 (phase C, a user's file with a log's header): a fresh blast SIGKILLed before its first commit; the user's notes.dat in postProcessing/solidProbes/0/ made of the run's own header lines (the first '#' lines of solidProbes.dat) followed by the user's rows; (b) the same in a restart segment killed before its first commit (fsi/1e-09/mine.dat with coupling.dat's header); -overwrite: refused by name, or removed?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.5; kill -KILL $p; wait $p 2>/dev/null; blastEnd 2e-9 1e-9
grep '^#' postProcessing/solidProbes/0/solidProbes.dat > postProcessing/solidProbes/0/notes.dat; echo "0 h04a user row" >> postProcessing/solidProbes/0/notes.dat; head -c 150 postProcessing/solidProbes/0/notes.dat | tr '\n' '|'; echo
tryf "(a) the log's header + user rows as notes.dat" cellBlastFoam -overwrite; kept "h04a user row"
cd $W; rm -rf blast; blast; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; latest; blastEnd 8e-9 4e-9
cellBlastFoam > log.2 2>&1 & p=$!; waitFor 60 test -d postProcessing/fsi/1e-09; waitFor 20 test -s postProcessing/fsi/1e-09/coupling.dat; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "   restart killed: fsi segments $(ls postProcessing/fsi | tr '\n' ' ')"
grep '^#' postProcessing/fsi/1e-09/coupling.dat > postProcessing/fsi/1e-09/mine.dat; echo "1e-09 h04b user row" >> postProcessing/fsi/1e-09/mine.dat
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; tryf "(b) coupling.dat's header + user rows in a killed restart's segment" cellBlastFoam -overwrite; kept "h04b user row"
