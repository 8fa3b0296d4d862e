#!/bin/bash
# w100: blast, 2 ranks to 10 ns: four SIGKILLs of the whole mpirun, each at a random moment 0-2.5 s after the start's next commit (inside steps and writes), then a last restart: bitwise the uninterrupted 2-rank run?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 10e-9 1e-9; latest; cp -r . ../ref; (cd ../ref && mpirun -np 2 cellBlastFoam -parallel > log.ref 2>&1; echo "reference rc=$?")
for i in 1 2 3 4; do n=$(( $(committed) + 1 )); s=$(/usr/bin/python3 -c "import random;print(round(random.uniform(0,2.5),2))"); mpirun -np 2 cellBlastFoam -parallel > log.k$i 2>&1 & p=$!; killAfter $n $p $s; done
run 200 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r; fatal log.r 6
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --bitwise --h5 2>&1 | cut -c1-200 | tail -4
