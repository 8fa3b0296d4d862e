#!/bin/bash
# k22 (class 5/1, incidentWindow.py on a restarted run with the reference of before): pw (planeWave's reference.dat computed at 2e-9), restarted to 4e-9 (the probes now reach 4e-9, the reference still 2e-9), incidentWindow.py on it; then the same reference in the quarter q (reconstructed: another case's reference, other probes). Expected: the stale reference named as shorter than the run or of another case (its probes/heights), or the measures taken over the span both cover and said; never a foreign reference used without a word.
. "$(dirname "$0")/../lib.sh"
pwd0; latest; blastEnd 4e-9 1e-9; tryt 300 "restart to 4e-9" cellBlastFoam; iw .; cat $W/try.log | head -8 | cut -c1-180 | sed 's/^/   /'
R=$PWD/postProcessing/planeWave/0/reference.dat; q; timeout 200 reconstructPar > /dev/null 2>&1; mkdir -p postProcessing/planeWave/0; cp $R postProcessing/planeWave/0/; iw .; cat $W/try.log | head -6 | cut -c1-180 | sed 's/^/   /'
