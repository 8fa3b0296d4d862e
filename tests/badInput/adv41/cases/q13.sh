#!/bin/bash
# q13: OpenFOAM's `postProcess` utility started WHILE cellBlastFoam runs in the case (to 8 ns): refused by the lock or harmless? the running run's logs then equal a run alone's?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 1e-9; cp -r $W/blast $W/ref; (cd $W/ref && cellBlastFoam > log.ref 2>&1; echo "reference rc=$?")
cellBlastFoam > log.run 2>&1 & p=$!; waitFor 60 test -f 2e-09/.writeCommitted; echo "lock: $(lockOf | cut -c1-80)"
tryf "postProcess beside the run" postProcess; wait $p; echo "the run: rc=$? $(tail -1 log.run)"; sameSeries $W/ref
cmp postProcessing/fluidProbes/0/p $W/ref/postProcessing/fluidProbes/0/p && echo "   fluidProbes/0/p equal to the reference"
