#!/bin/bash
# x30: blast to 2e-8 writing every 1 ns, SIGKILLed after its 2nd commit (logs then hold rows past the last commit); the user 'tidies' the log: deletes the rows after the last committed time (bytes beyond the recorded size) / edits one digit in a row after it; restart: accepted (those rows are recomputed), logs bitwise an uninterrupted run?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 6e-9 1e-9; cellBlastFoam > log.ref 2>&1; cp -r . ../ref; rm -rf [1-9]* solid postProcessing
cellBlastFoam > log.first 2>&1 & p=$!; killAfter 2 $p 0.4; t=$(ls -d [1-9]*/.writeCommitted | sort -g | tail -1 | cut -d/ -f1); echo "last committed $t"
f=postProcessing/fsi/0/coupling.dat; n=$(wc -l < $f); tail -2 $f | cut -c1-80; awk -v t=$t 'NR>1 && $1+0 > t+1e-15 {c++} END{print c+0, "rows after", t}' $f
awk -v t=$t '/^#/ || $1+0 <= t+1e-15' $f > ../c; cp ../c $f; latest; run 120 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 4
sameSeries ../ref
