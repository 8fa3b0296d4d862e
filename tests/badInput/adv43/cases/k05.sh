#!/bin/bash
# k05 (class 2, the indentation's output folder): a run killed after its first checkpoint; the user's notes.md, a copy force.dat.bak and myPlots/a.png in postProcessing/indentation/; restart (latestTime) to the end: kept? then -overwrite (startFrom startTime): refused naming them or kept?
. "$(dirname "$0")/../lib.sh"
indKilled 0.5; D=postProcessing/indentation; echo "# k05 my notes" > $D/notes.md; cp $D/force.dat $D/force.dat.bak; echo "k05 bak row" >> $D/force.dat.bak; mkdir -p $D/myPlots; echo "k05 png" > $D/myPlots/a.png
tryf "restart (latestTime) to the end" cellIndentationFoam; echo "   $D: $(ls -a $D | tr '\n' ' ')"; kept "k05 my notes" "k05 bak row" "k05 png"; forceOk $D/force.dat
restart0; sums > ../s; tryf "-overwrite" cellIndentationFoam -overwrite; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -4 | cut -c1-160; nochange ../s; kept "k05 my notes" "k05 bak row" "k05 png"
