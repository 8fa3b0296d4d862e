#!/bin/bash
# g72 (class 3, sweepCase on a case that is running) bd restarting to 1e-8 in the background (holding its lock, writing times); sweepCase -case . over constant/fsiProperties coupling/maxIter (one value, -run true, -keep): refused naming the run (the case in use), nothing copied; or its copy holds no live lock and no half-written time (listed here). Never a copy of a run in progress taken as a case.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -s .runLock; sleep 3; echo "   run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
tryt 120 "sweepCase during the run" sweepCase -case . -entry constant/fsiProperties/coupling/maxIter -values "31" -output "x=postProcessing/fsi/0/coupling.dat:max:2" -run true -keep -name live; tail -2 $W/try.log | cut -c1-200
for c in $(ls -d $W/blast.sweep* $W/*sweep* 2>/dev/null | sort -u); do echo "   copy $c: lock $(head -c 80 $c/.runLock 2>/dev/null | tr '\n' ';' || echo none), times $(ls -d $c/[0-9]* 2>/dev/null | xargs -n1 basename | tr '\n' ' '), in progress: $(ls -d $c/*/.writeInProgress 2>/dev/null | tr '\n' ' ')"; done
wait $p; echo "   run rc=$?"; after
