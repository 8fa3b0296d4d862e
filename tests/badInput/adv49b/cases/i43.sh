#!/bin/bash
# i43 (class 5/SILENT, planeWave -check on a half-finished run): xbd's prepared case run from 0 to 6e-9 and SIGKILLed after
# its 2nd commit (the logs reach about 2-3 ns of 6): `planeWave -check` must say the run is incomplete (its logs end before
# endTime: the times it covers) or refuse; never pass a check over times it does not have. `planeWave -check -partial`:
# checks what there is and says up to which time. Then the finished base xbd (to 5e-9): -check exits 0 or names its
# failures (compared with the killed run's output: the killed one must not say more passed than it has).
. "$(dirname "$0")/../lib.sh"
xbd; B=$PWD; cp -a $B $W/k; cd $W/k; fresh; e6; cellBlastFoam > log.killed 2>&1 & p=$!; killAfter 2 $p; rm -f .runLock; echo "   logs end at $(tail -1 postProcessing/fsi/0/coupling.dat | cut -c1-14)"; sums > ../s0
tryt 300 "killed run: planeWave -check" planeWave -check; tail -6 $W/try.log | cut -c1-200 | sed 's/^/   /'; echo "   changed: $(changed ../s0)"
tryt 300 "killed run: planeWave -check -partial" planeWave -check -partial; tail -4 $W/try.log | cut -c1-200 | sed 's/^/   /'
cd $B; tryt 300 "finished base: planeWave -check" planeWave -check; tail -6 $W/try.log | cut -c1-200 | sed 's/^/   /'
