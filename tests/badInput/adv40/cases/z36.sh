#!/bin/bash
# z36: `cellBlastFoam -postProcess` started in a case WHILE its cellBlastFoam runs (to 8 ns): refused by the lock (one run per case), or does it rewrite the running run's probe log? the running run's logs then equal a run alone's (sameSeries)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 1e-9; cp -r $W/blast $W/ref; (cd $W/ref && cellBlastFoam > log.ref 2>&1; echo "reference rc=$?")
cellBlastFoam > log.run 2>&1 & p=$!; waitFor 60 test -f 2e-09/.writeCommitted; echo "lock: $(lockOf | cut -c1-80)"
tryf "-postProcess beside the run" cellBlastFoam -postProcess; wait $p; echo "the run: rc=$? $(tail -1 log.run)"; sameSeries $W/ref
