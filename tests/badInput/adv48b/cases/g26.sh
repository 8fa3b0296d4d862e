#!/bin/bash
# g26 (class 2/3, Allclean while the case runs) bd restarted to 3e-9 in the background; once it holds the lock, the preview's ./Allclean: refused naming the run (the case is in use), nothing removed; the run then finishes with times 1e-09 2e-09 3e-09 and solid.h5 of 3 steps. Never the run's results removed under it.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean .; cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -s .runLock; sleep 2; tryt 60 "Allclean during the run" ./Allclean; tail -2 $W/try.log | cut -c1-200; echo "   right after Allclean: $(ls -d [0-9]* solid postProcessing 2>/dev/null | tr '\n' ' ')"
wait $p; echo "   run rc=$? $(grep -a -m1 'FATAL\|End' ../run.log)"; after
