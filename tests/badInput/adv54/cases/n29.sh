#!/bin/bash
# CASETIMEOUT=600
# n29 (new, class 5: a column file our scripts write and another script measures, without a digest - reliability.md's
# documented limit "measures.dat, table.csv ... are not digested", fix19k item 2's class): p8 (finished, planeWave run)
# laid out as a transparentCell.sh run (DIR/axisymmetricPreview); bench/blast/transparentLadder.py -item1 x1=DIR, then
# again after postProcessing/planeWave/0/measures.dat's fluid row edited (errPeak1ns -1.8549 -> +9.9, a user's "fix"),
# and after solidMeasures.dat's first row's errVonMises x10. Expected (issue 19 class 5): the edited files refused
# naming the line; the ladder tabling the edited numbers without a word = SILENT (documented limit, still SILENT).
. "$(dirname "$0")/../lib.sh"
p8; mkdir -p $W/D; mv $W/p8 $W/D/axisymmetricPreview; cd $W/D/axisymmetricPreview; [ -f log.checkMesh ] || echo "   (no log.checkMesh)"; L=$ROOT/bench/blast/transparentLadder.py
tryt 120 "(0) transparentLadder.py -item1 as written" /usr/bin/python3 $L -item1 x1=$W/D; grep -a 'x1' $W/try.log | head -2 | cut -c1-250
sed -i 's/-1.8549 -1.8549/9.9 -1.8549/' postProcessing/planeWave/0/measures.dat; grep -a '^fluidProbes' postProcessing/planeWave/0/measures.dat | cut -c1-200
tryt 120 "(a) measures.dat's errPeak1ns edited" /usr/bin/python3 $L -item1 x1=$W/D; echo "   said: $(say 1 | cut -c1-200)"; grep -a 'x1' $W/try.log | head -2 | cut -c1-250
