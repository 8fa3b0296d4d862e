#!/bin/bash
# x03: indentation Allrun (fine steps): its shell alone SIGTERMed while the solver runs; then cellMesh by hand (it would rewrite constant/cell.msh under the running solver) and sweepCase on the case: both refused naming the orphan solver?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
./Allrun > log.a1 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; kill -TERM $p; wait $p 2>/dev/null; echo "shell SIGTERMed; lock: $(lockOf)"
md5sum constant/cell.msh > ../m1
run 60 cellMesh > log.hand 2>&1; fatal log.hand 3; md5sum -c ../m1
run 60 sweepCase -entry constant/indenterProperties/holdGrowth -values '1.5 1.4' -run cellIndentationFoam -output 'peaks.dat:F' -name hg > log.sweep 2>&1; fatal log.sweep 3
wait_s=$(sed -n "s/^pid //p" .runLock 2>/dev/null | head -1); while kill -0 ${wait_s:-0} 2>/dev/null; do sleep 0.5; done; echo "solver over; lock: $(lockOf)"; tail -1 log.cellIndentationFoam
