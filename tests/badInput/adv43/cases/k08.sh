#!/bin/bash
# k08 (class 2, planeWave's folders): a blast finished to 2 ns; planeWave (-Z 20e-6 -dz 0.25e-6) run once; the user's notes.md and measures.dat.mine in postProcessing/planeWave/0/ and notes.md in postProcessing/planeWave/; planeWave again (and -layered): kept? then cellBlastFoam -overwrite from 0 with them there: kept or refused by name?
. "$(dirname "$0")/../lib.sh"
blastDone; run 150 planeWave -Z 20e-6 -dz 0.25e-6 > ../log.pw1 2>&1; grep -a -i -m2 'error\|Traceback' ../log.pw1 | cut -c1-200; D=postProcessing/planeWave; echo "   $D/0: $(ls -a $D/0 2>/dev/null | tr '\n' ' ')"
echo "# k08 my wave notes" > $D/0/notes.md; cp $D/0/measures.dat $D/0/measures.dat.mine; echo "k08 mine row" >> $D/0/measures.dat.mine; echo "k08 top notes" > $D/notes.md
run 150 planeWave -Z 20e-6 -dz 0.25e-6 > ../log.pw2 2>&1; grep -a -i -m2 'error\|refus\|Traceback' ../log.pw2 | cut -c1-200; kept "k08 my wave notes" "k08 mine row" "k08 top notes"
restart0; blastEnd 2e-9 1e-9; sums > ../s; tryf "cellBlastFoam -overwrite from 0" cellBlastFoam -overwrite; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -4 | cut -c1-160; nochange ../s; kept "k08 my wave notes" "k08 mine row" "k08 top notes"
