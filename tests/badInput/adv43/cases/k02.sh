#!/bin/bash
# k02 (class 2, a user's file bearing EXACTLY the name the restart will write, in the folder it writes): a blast finished to 2 ns; the user's own postProcessing/fsi/2e-09/coupling.dat ("k02 my coupling table", no header) and fluidProbes/2e-09/p ("k02 my p notes") made before the restart 2 -> 3 ns: refused naming them, or written over (the user's text gone)?
. "$(dirname "$0")/../lib.sh"
blastDone; P=postProcessing; mkdir -p $P/fsi/2e-09 $P/fluidProbes/2e-09; echo "k02 my coupling table" > $P/fsi/2e-09/coupling.dat; echo "k02 my p notes" > $P/fluidProbes/2e-09/p
latest; blastEnd 3e-9 1e-9; sums > ../s; tryf "restart 2 -> 3 ns" cellBlastFoam; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -4 | cut -c1-160; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kept "k02 my coupling table" "k02 my p notes"
echo "   fsi/2e-09: $(ls -a $P/fsi/2e-09 | tr '\n' ' '); fluidProbes/2e-09: $(ls -a $P/fluidProbes/2e-09 | tr '\n' ' ')"
