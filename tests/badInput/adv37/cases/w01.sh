#!/bin/bash
# w01: blast, 2 ranks to 10 ns: SIGKILL of mpirun and its ranks at random moments (after 1, then 4 commits, +0-0.3 s), restarted with latestTime on 2 ranks: bitwise the uninterrupted 2-rank run (probes and solid.h5)?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 10e-9 1e-9; latest; cp -r . ../ref; (cd ../ref && mpirun -np 2 cellBlastFoam -parallel > log.ref 2>&1; echo "reference rc=$?")
mpirun -np 2 cellBlastFoam -parallel > log.k1 2>&1 & p=$!; killAfter 1 $p
mpirun -np 2 cellBlastFoam -parallel > log.k2 2>&1 & p=$!; killAfter 4 $p
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r; fatal log.r
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --bitwise --h5 2>&1 | tail -3
