#!/bin/bash
# CASETIMEOUT=900
# l33 (new, class 2: u10 after an interrupted run - a script killed before its end (a record of its outputs, if written
# at the end, is not there), the user's notes added to its case, the script run again): tests/blast/runPreview.sh DIR
# (to 200e-9) started in a process group of its own and SIGKILLed whole 4 s later (its solver running); the user adds
# DIR/axisymmetricPreview/logbook.txt, results.md and postProcessing/notes.txt; (a) runPreview.sh DIR -noRun again;
# (b) the same with DIR's stale .scratchLock/.runLock left by the kill. Expected: the user's files refused and kept
# (nothing removed that the script cannot tell is its own); removed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -noPlots -noVTK"
cd $W; setsid bash $ROOT/tests/blast/runPreview.sh $W/d $O -endTime 200e-9 > $W/r1.log 2>&1 & p=$!; sleep 4; kill -KILL -- -$p 2>/dev/null; sleep 1; killIn $W/d; sleep 0.5
C=d/axisymmetricPreview; echo "   killed at 4 s: $(ls -A $C | tr '\n' ' ' | cut -c1-250) | DIR: $(ls -A d | tr '\n' ' ')"
for f in logbook.txt results.md postProcessing/notes.txt; do mark $C/$f; done
tryt 300 "(a) runPreview.sh DIR -noRun after the killed run, the user's files added" bash $ROOT/tests/blast/runPreview.sh $W/d $O -noRun; echo "   said: $(say 3 | cut -c1-300)"
for f in logbook.txt results.md postProcessing/notes.txt; do kept_ $C/$f; done
