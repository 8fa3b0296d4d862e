#!/bin/bash
# g08 (class 1, decomposePar/reconstructPar with a changed decomposition): (a) 2 ranks split at y = 4 um run to 2 ns, reconstructPar, re-split at y = 6 um with decomposePar -force -latestTime, 2-rank restart to 3 ns; (b) a serial run to 2 ns, decomposePar -latestTime (y = 4 um), 2-rank restart to 3 ns. Refused naming the decomposition, or continued with results close to a serial run's to 3 ns (no repeated or missing times, solid.h5 3 steps)?
. "$(dirname "$0")/../lib.sh"
blastRef
pblastDone; echo "   2 ranks to 2 ns: $(ls -d processor0/[1-9]* | tr '\n' ' ')"; reconstructPar > log.rec 2>&1; echo "   reconstructPar rc $?: $(ls -d [1-9]* | tr '\n' ' ')"
splitY 6e-6; decomposePar -force -latestTime > log.dec2 2>&1; echo "   decomposePar -force -latestTime (y = 6 um) rc $?: processor0 $(ls processor0 | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; tryf "(a) 2-rank restart after the re-split" mpirun -np 2 cellBlastFoam -parallel; grep -a -A3 'other inputs\|FATAL' $W/try.log | head -4 | cut -c1-200
echo "   times processor0: $(ls -d processor0/[1-9]* 2>/dev/null | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5), xmf $(xmfsteps solid/solid.xmf)"; closeTo $W/r/ref
cd $W; rm -rf blast; blastDone; splitY 4e-6; decomposePar -latestTime > log.dec 2>&1; echo "   (b) serial to 2 ns, decomposePar -latestTime rc $?: processor0 $(ls processor0 | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; tryf "(b) 2-rank restart of the serial run" mpirun -np 2 cellBlastFoam -parallel; grep -a -A3 'other inputs\|FATAL' $W/try.log | head -4 | cut -c1-200
echo "   times: case $(ls -d [1-9]* | tr '\n' ' ') processor0 $(ls -d processor0/[1-9]* 2>/dev/null | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5), xmf $(xmfsteps solid/solid.xmf)"; closeTo $W/r/ref
