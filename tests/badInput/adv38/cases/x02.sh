#!/bin/bash
# x02: indentation Allrun (10x finer steps): its shell alone SIGKILLed while the solver runs; a second ./Allrun at once (refused naming the live solver?); then after the orphan solver finished, ./Allrun again: the solver ended well, but runStep's log.cellIndentationFoam.running is left: does the third Allrun call the complete run "stopped before its end ... partial"?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
./Allrun > log.a1 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; kill -KILL $p; wait $p 2>/dev/null; echo "shell killed; lock: $(lockOf)"
run 60 ./Allrun > log.a2 2>&1; fatal log.a2 3
s=$(sed -n "s/^pid //p" .runLock | head -1)
echo "orphan solver pid $s"; while kill -0 $s 2>/dev/null; do sleep 0.5; done
echo "orphan over; log end: $(tail -2 log.cellIndentationFoam | tr '\n' ' ')"; echo "lock: $(lockOf)"; ls log.*
run 120 ./Allrun > log.a3 2>&1; cat log.a3 | cut -c1-400 | head -8
