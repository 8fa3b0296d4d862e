#!/bin/bash
# CASETIMEOUT=600
# n09 (new, class 3: tutorials/paper's Allclean, which removes postProcessing/ where paperFigures runs the runs it misses,
# postProcessing/runs/<name>): a copy of tutorials/paper ($W/paper) whose postProcessing/runs/preview holds a solver
# running (the finished preview bd restarted to 4e-8), and postProcessing/paper a finished output: (a) $W/paper/Allclean
# while that run goes; (b) the same Allclean after the run (control: removes the outputs, by design). Never a running
# run's case removed: refused naming the run (its lock), nothing removed.
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; mkdir -p $W/paper/postProcessing/runs $W/paper/postProcessing/paper; echo "figures" > $W/paper/postProcessing/paper/README.md
bd; latest; blastEnd 4e-8 1e-9; rm -f .runLock; cd $W; mv blast $W/paper/postProcessing/runs/preview; C=$W/paper/postProcessing/runs/preview; cd $C
(cellBlastFoam > $W/bg.log 2>&1; echo "bg rc $?" >> $W/bg.log) & bp=$!; sleep 4; echo "lock: $(head -c 150 .runLock 2>/dev/null | tr '\n' ' ')"
cd $W/paper; tryt 60 "(a) tutorials/paper's Allclean while a run in postProcessing/runs/preview goes" ./Allclean; echo "   postProcessing now: $(ls -R postProcessing 2>/dev/null | head -5 | tr '\n' ' ' | cut -c1-200) | the run's case: $(ls $C 2>/dev/null | head -5 | tr '\n' ' ')"
wait $bp; echo "   solver: $(tail -2 $W/bg.log | tr '\n' ' ' | cut -c1-250)"
tryt 60 "(b) the same Allclean after the run" ./Allclean; echo "   postProcessing now: $(ls postProcessing 2>/dev/null | tr '\n' ' ')"
