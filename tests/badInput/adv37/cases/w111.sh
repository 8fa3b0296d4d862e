#!/bin/bash
# w111: planeWave on a finished run after the user set the NEXT run's pulse in 0/p (50 -> 30 MPa): compares the run's probes with the 1D wave of a pulse the run did not have, without a word?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 14e-9 7e-9; cellBlastFoam > log.first 2>&1; echo "run rc=$?"; planeWave -case . > log.pw0 2>&1; echo "before rc=$?"; cp -r postProcessing/planeWave ../pw0
sed -i 's/50000000/30000000/g' 0/p; try after planeWave -case .; grep -a -i "0/p\|pulse\|changed\|differ" $W/try.log | head -3 | cut -c1-200
f=../pw0/0/measures.dat; echo "measures.dat: probe, peak1ns and its reference, error: before | after"; paste <(grep -v '^#' $f | awk '{print $1, $5, $6, $NF}') <(grep -v '^#' postProcessing/planeWave/0/measures.dat | awk '{print $5, $6, $NF}') | head -3
