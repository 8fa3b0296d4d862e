#!/bin/bash
# k10 (class 2, processor*/ and 2 ranks): a 2-rank blast finished to 2 ns; before a 2-rank restart to 3 ns the user's notes.md in postProcessing/fsi/2e-09/ and solidProbes/2e-09/ (g35's shape on 2 ranks) and processor0/2e-09/uniform/k10.txt; restart: kept? markers? then 2-rank -overwrite from 0: refused naming them (on the rank that prints), all kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; P=postProcessing; mkdir -p $P/fsi/2e-09 $P/solidProbes/2e-09; echo "# k10 fsi seg notes" > $P/fsi/2e-09/notes.md; echo "k10 probes seg notes" > $P/solidProbes/2e-09/notes.txt; echo "k10 uniform" > processor0/2e-09/uniform/k10.txt
latest; blastEnd 3e-9 1e-9; tryf "2-rank restart 2 -> 3 ns" mpirun -np 2 cellBlastFoam -parallel; echo "   times p1: $(ls -d processor1/[1-9]* | tr '\n' ' ')"; kept "k10 fsi seg notes" "k10 probes seg notes" "k10 uniform"; marks notes.md; marks notes.txt
restart0; blastEnd 2e-9 1e-9; sums > ../s; tryf "2-rank -overwrite from 0" mpirun -np 2 cellBlastFoam -parallel -overwrite; grep -a 'postProcessing\|uniform' $W/try.log | grep -v '^-->' | head -6 | cut -c1-160; nochange ../s; kept "k10 fsi seg notes" "k10 probes seg notes" "k10 uniform"
