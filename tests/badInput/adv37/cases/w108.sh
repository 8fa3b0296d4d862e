#!/bin/bash
# w108: blast, 2 ranks, a fresh case: the run SIGKILLed before its first write (as soon as postProcessing/ appears), then a restart with startFrom latestTime (the documented way after a kill): continues, or refused with a message that fits?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 10e-9 1e-9; latest; mpirun -np 2 cellBlastFoam -parallel > log.k 2>&1 & p=$!; i=0; until [ -d postProcessing ] || [ $i -ge 600 ]; do sleep 0.05; i=$((i+1)); done; sleep 0.3; pkill -KILL -P $p; kill -KILL $p; wait $p 2>/dev/null
echo "killed: $(committed) committed; left: $(find solid postProcessing -type f | tr '\n' ' ')"; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 8; tail -1 log.r
