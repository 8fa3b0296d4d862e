#!/bin/bash
# w86: blast 2 ranks: -overwrite (to 6 ns) SIGKILLed before its first commit, then the restart's advice: earlier 2-rank results all back, and a restart continues?
. "$(dirname "$0")/../lib.sh"
pblastDone; snap ../before; blastEnd 6e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ow 2>&1 & p=$!; sleep 0.8; pkill -KILL -P $p; kill -KILL $p; wait $p 2>/dev/null
echo "after the kill, gone: $(gone ../before | tr '\n' ' ')"; ls -a . processor1 | tr '\n' ' '; echo
latest; run 60 mpirun -np 2 cellBlastFoam -parallel > log.r1 2>&1; fatal log.r1 14
