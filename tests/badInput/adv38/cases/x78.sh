#!/bin/bash
# x78: planeWave -partial (documented: reads a running case without the lock) called up to 8 times while cellBlastFoam runs (to 12 ns, writes every 1 ns): any traceback or error on a half-written row or time, any file of the run changed?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 12e-9 1e-9; cellBlastFoam > log.run 2>&1 & p=$!; waitFor 60 test -d 2e-09
for k in 1 2 3 4 5 6 7 8; do planeWave -partial -Z 20e-6 -dz 50e-9 > ../pw$k.log 2>&1; echo "partial $k: rc=$? $(grep -a -i -m1 'error\|Traceback' ../pw$k.log | cut -c1-200)"; kill -0 $p 2>/dev/null || break; done
wait $p; echo "run exit $?"; tail -1 log.run
