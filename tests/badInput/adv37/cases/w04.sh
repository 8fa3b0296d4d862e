#!/bin/bash
# w04: blast: a 2-rank run finished (results in processor*/ and the root's solid/, postProcessing/); the user restarts in SERIAL with latestTime (no reconstructPar): root latest time is 0. Are the parallel run's solid.h5 and postProcessing kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; contents > ../before; latest; blastEnd 4e-9 1e-9
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 8; echo "lost:"; lost ../before | wc -l; ls -a . solid | tr '\n' ' '
