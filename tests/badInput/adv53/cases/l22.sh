#!/bin/bash
# CASETIMEOUT=900
# l22 (new, class 2: u10's name patterns in another script - outputFolder's "@case" takes any name a case may hold for
# the script's own): tutorials/indentation/gapStudy.sh averageCell base (WORK=$W/g) run once; the user then adds to its
# case folder WORK/averageCell_base: log.myNotes, 1-interpretation.txt, results.md, fit.png, a notes file inside
# postProcessing/ and constant/; gapStudy.sh averageCell base again. Expected: refused naming the user's files, all
# kept (reliability.md fix19i: "a user's file added to the script's earlier output (also inside its case folder) is
# refused and kept"); removed by the second run = DATALOSS.
. "$(dirname "$0")/../lib.sh"
cd $W; tryt 600 "(0) WORK=$W/g gapStudy.sh averageCell base" env WORK=$W/g bash $ROOT/tutorials/indentation/gapStudy.sh averageCell base; echo "   last: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-200) | case: $(ls $W/g/averageCell_base | tr '\n' ' ' | cut -c1-200)"
C=g/averageCell_base; for f in log.myNotes 1-interpretation.txt results.md fit.png postProcessing/myNotes.txt constant/myNotes; do mark $C/$f; done
tryt 600 "(a) gapStudy.sh averageCell base again, the user's files in its case" env WORK=$W/g bash $ROOT/tutorials/indentation/gapStudy.sh averageCell base; echo "   said: $(say 3 | cut -c1-300)"
for f in log.myNotes 1-interpretation.txt results.md fit.png postProcessing/myNotes.txt constant/myNotes; do kept_ $C/$f; done
