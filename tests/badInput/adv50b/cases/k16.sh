#!/bin/bash
# k16 (class 3/5, planeWave while the run writes): bd restarted to 30e-9 in the background; while it runs: planeWave -case . (the 1D answer and the probes' measures) and planeWave -case . -check. Expected: planeWave names the case as running or cut (its probes end before endTime), -check refuses without -partial; the running run is not disturbed (its lock, its logs) and ends; planeWave's files are not taken for a finished run's.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 30e-9 1e-9; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 2
tryt 300 "planeWave while the run goes" planeWave -case .; grep -a -i -m3 'cut\|running\|partial\|still' $W/try.log | cut -c1-200 | sed 's/^/   pw: /'
tryt 300 "planeWave -check while the run goes" planeWave -case . -check; grep -a -i -m3 'cut\|running\|partial\|still' $W/try.log | cut -c1-200 | sed 's/^/   pw: /'
echo "   run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"; wait $p; echo "   run rc=$? | $(grep -a -m2 'FATAL\|End' log.bg | tr '\n' ' ')"; after
