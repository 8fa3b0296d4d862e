#!/bin/bash
# CASETIMEOUT=900
# l32 (new, class 5/2: the text results of a run killed at random moments, read as they are - a digest scheme for these
# files (fix19j item 2) must not take a killed run's honest rows for a hand edit, nor lose them at the restart): (a) the
# smoke indentation with 10x finer depth steps SIGKILLed at 1.0, 1.7, 2.3 s (three runs), then plotIndentation.py on
# what is left; then the restart to its end and plotIndentation.py again; (b) the preview restarted to 20e-9, SIGKILLed
# at 2.5 s, then incidentWindow.py / planeWave -check -partial on it, then the restart to its end. Expected: (a) the
# killed run's files read (or said partial), never "edited by hand"; after the restart the table equals an uninterrupted
# run's (force.dat bitwise); (b) the same for the blast's logs.
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -a . $W/i0; tryt 600 "(0) uninterrupted" cellIndentationFoam; cp postProcessing/indentation/force.dat $W/f.ref; cp postProcessing/indentation/peaks.dat $W/pk.ref
for s in 1.0 1.7 2.3; do cd $W; rm -rf ind; cp -a i0 ind; cd ind; cellIndentationFoam > log.a 2>&1 & p=$!; sleep $s; kill -KILL $p; wait $p 2>/dev/null
  tryt 120 "(a) killed at $s s: plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .; echo "   said: $(grep -a -i -m2 'error\|edited\|hand\|digest\|partial\|Traceback' $W/try.log | tr '\n' '|' | cut -c1-250) | force rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null)"
  rm -f .runLock; sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict; tryt 600 "(a) killed at $s s: the restart" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | force.dat $(cmp -s postProcessing/indentation/force.dat $W/f.ref && echo same || echo DIFFERS) | peaks.dat $(cmp -s postProcessing/indentation/peaks.dat $W/pk.ref && echo same || echo DIFFERS)"
  tryt 120 "(a) killed at $s s, restarted: plotIndentation.py" /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .; echo "   said: $(grep -a -i -m2 'error\|edited\|hand\|digest\|Traceback' $W/try.log | tr '\n' '|' | cut -c1-250) | C1,i: $(grep -a 'C1,i ' $W/try.log | head -1 | tr -s ' ')"; done
cd $W; bd; latest; blastEnd 20e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 & p=$!; sleep 2.5; kill -KILL $p; wait $p 2>/dev/null; echo "   (b) killed at 2.5 s: times $(ls -d [0-9]* | tr '\n' ' ')"
iw .; echo "   incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-200)"
tryt 300 "(b) planeWave -partial on the killed case" planeWave -case . -partial; echo "   said: $(say 2 | cut -c1-200) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-150)"
rm -f .runLock; tryt 600 "(b) the restart to 20e-9" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"
tryt 300 "(b) planeWave -check after the restart" planeWave -case . -check; echo "   said: $(say 2 | cut -c1-200) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-150)"
