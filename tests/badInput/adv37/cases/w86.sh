#!/bin/bash
# w86: blast 2 ranks: -overwrite (to 6 ns) SIGKILLed as soon as it has moved the earlier times aside (before its first commit), then the restart's advice: earlier 2-rank results all still there, and the restart says what to do?
. "$(dirname "$0")/../lib.sh"
pblastDone; snap ../before; blastEnd 6e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ow 2>&1 & p=$!
i=0; until ls -a processor1 processor0 . 2>/dev/null | grep -q overwritten || [ $i -ge 400 ]; do sleep 0.05; i=$((i+1)); done; pkill -KILL -P $p; kill -KILL $p; wait $p 2>/dev/null
echo "killed after $((i*5/100)) s; gone: $(gone ../before | tr '\n' ' ')"; ls -a . processor1 solid | tr '\n' ' '; echo
latest; run 60 mpirun -np 2 cellBlastFoam -parallel > log.r1 2>&1; fatal log.r1 14; tail -1 log.r1
echo "-- the advice's loop, verbatim, then the restart:"; find . -depth -name '.*.overwritten' | while read -r p; do n=${p##*/}; t=${p%/*}/${n#.}; t=${t%.overwritten}; rm -rf "$t"; mv "$p" "$t"; done
echo "gone now: $(gone ../before | tr '\n' ' ')"; ls processor1 | tr '\n' ' '; echo; run 120 mpirun -np 2 cellBlastFoam -parallel > log.r2 2>&1; fatal log.r2 6; tail -1 log.r2
