#!/bin/bash
# k03 (class 2, DURING a live fresh run the user copies logs across function objects' folders): blast to 6 ns; after 1e-09 is committed: cp solidProbes/0/solidProbes.dat solidInterfaces/0/ (right header, wrong folder); cp fluidProbes/0/p fsi/0/p; a plain-text coupling.dat into fluidProbes/0/; a subfolder fsi/0/plots/a.png and a hidden solidProbes/0/.k03notes; the run ends; what do the markers record? -overwrite from 0: refused naming all five, kept?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 6e-9 1e-9; P=postProcessing; cellBlastFoam > log.first 2>&1 & p=$!; waitFor 60 test -f 1e-09/.writeCommitted
cp $P/solidProbes/0/solidProbes.dat $P/solidInterfaces/0/solidProbes.dat; cp $P/fluidProbes/0/p $P/fsi/0/p; echo "k03 coupling in fluidProbes" > $P/fluidProbes/0/coupling.dat; mkdir -p $P/fsi/0/plots; echo "k03 png" > $P/fsi/0/plots/a.png; echo "k03 hidden" > $P/solidProbes/0/.k03notes
md5sum $P/solidInterfaces/0/solidProbes.dat $P/fsi/0/p > ../m; wait $p; echo "   run rc $?: times $(ls -d [1-9]* | tr '\n' ' ')"
for t in solidInterfaces/0/solidProbes.dat fsi/0/p fluidProbes/0/coupling.dat plots/a.png .k03notes; do marks $t; done
blastEnd 2e-9 1e-9; sums > ../s; tryf "-overwrite from 0" cellBlastFoam -overwrite; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -6 | cut -c1-160; nochange ../s
kept "k03 coupling in fluidProbes" "k03 png" "k03 hidden"; echo "   copies (as copied: the original run's first rows): $(md5sum -c ../m 2>&1 | tr '\n' ' ')"
