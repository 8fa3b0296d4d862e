#!/bin/bash
# k18 (class 5/2, checkQuarterRun.sh on a cut run and over a user's files): q reconstructed (reconstructPar), its controlDict endTime set to 1.5e-7 (the run stopped at 2e-9 of 150 ns), a user's note and a user's reference.dat in postProcessing/planeWave/0/. Expected: exit non-zero naming the run as unfinished (checkLongRun: not at endTime); the user's note kept; a file planeWave replaces is planeWave's own (or the user's file named and kept). (P1b: log.first copied to log.cellBlastFoam, the name the Allrun gives the solver log, which checkLongRun.py reads)
. "$(dirname "$0")/../lib.sh"
q; cp log.first log.cellBlastFoam; timeout 200 reconstructPar > $W/rp.log 2>&1; echo "   reconstructPar rc=$? times: $(ls -d [0-9]* | tr '\n' ' ')"
qEnd 1.5e-7; mkdir -p postProcessing/planeWave/0; echo "my note" > postProcessing/planeWave/0/notes.txt; echo "# my own reference" > postProcessing/planeWave/0/reference.dat
tryt 600 "checkQuarterRun on the cut run" bash $ROOT/tests/blast/checkQuarterRun.sh .; tail -4 $W/try.log | cut -c1-200 | sed 's/^/   /'
kept "my note" "my own reference"; ls postProcessing/planeWave/0/ | tr '\n' ' '; echo
