#!/bin/bash
# w02: blast, 2 ranks: only rank 1's process SIGKILLed mid-run: does mpirun end (no hang), and does a 2-rank restart continue to the end?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 6e-9 1e-9; latest
mpirun -np 2 cellBlastFoam -parallel > log.k 2>&1 & p=$!; sleep 1; r1=$(pgrep -P $p -f cellBlastFoam | tail -1); ps -o pid,args -p $(pgrep -d, -P $p) | cut -c1-80
kill -KILL $r1; s=0; while kill -0 $p 2>/dev/null && [ $s -lt 60 ]; do sleep 1; s=$((s+1)); done; kill -0 $p 2>/dev/null && { echo "HANG: mpirun alive 60 s after rank 1 died"; pkill -KILL -P $p; kill -KILL $p; }; wait $p; echo "mpirun rc=$? after ${s}s"
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r; fatal log.r; ls processor0 | tr '\n' ' '
