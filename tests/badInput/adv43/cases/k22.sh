#!/bin/bash
# k22 (class 2, k02 on 2 ranks; added after k02's result): a 2-rank blast finished to 2 ns; the user's own postProcessing/fsi/2e-09/coupling.dat and solidProbes/2e-09/solidProbes.dat (plain text) before the 2-rank restart to 3 ns: refused naming them, or written over?
. "$(dirname "$0")/../lib.sh"
pblastDone; P=postProcessing; mkdir -p $P/fsi/2e-09 $P/solidProbes/2e-09; echo "k22 my coupling" > $P/fsi/2e-09/coupling.dat; echo "k22 my probes" > $P/solidProbes/2e-09/solidProbes.dat
latest; blastEnd 3e-9 1e-9; tryf "2-rank restart 2 -> 3 ns" mpirun -np 2 cellBlastFoam -parallel; echo "   times p1: $(ls -d processor1/[1-9]* | tr '\n' ' ')"; kept "k22 my coupling" "k22 my probes"
