#!/bin/bash
# w100: blast, 2 ranks to 10 ns: four SIGKILLs of the whole mpirun at uniformly random moments (0.2-3 s after each start, not tied to writes), then a last restart: bitwise the uninterrupted 2-rank run?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 10e-9 1e-9; latest; cp -r . ../ref; (cd ../ref && mpirun -np 2 cellBlastFoam -parallel > log.ref 2>&1; echo "reference rc=$?")
for i in 1 2 3 4; do s=$(/usr/bin/python3 -c "import random;print(round(random.uniform(0.2,3),2))"); mpirun -np 2 cellBlastFoam -parallel > log.k$i 2>&1 & p=$!; sleep $s; pkill -KILL -P $p; kill -KILL $p 2>/dev/null; wait $p 2>/dev/null; echo "kill $i at $s s: $(committed) committed; $(ls -d processor1/*.incomplete 2>/dev/null | wc -l) incomplete"; done
run 200 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; tail -1 log.r; fatal log.r 6
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../ref . --bitwise --h5 2>&1 | cut -c1-200 | tail -4
