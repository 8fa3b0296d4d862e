#!/bin/bash
# f20 (class 2, reconstructPar over a restarted parallel run, then the parallel run goes on): q restarted on 2 ranks to 3e-9, reconstructPar (times 1e-09..3e-09 in the root), then the parallel restart to 4e-9: continues (the reconstructed times are the same run's) rc 0 - and afterwards reconstructPar -newTimes adds 4e-09; the root's 3e-09 is not replaced by a differing copy, no results lost.
. "$(dirname "$0")/../lib.sh"
q; latest; qEnd 3e-9; tryt 280 "parallel restart to 3e-9" mpirun -np 2 cellBlastFoam -parallel; tryt 120 "reconstructPar" reconstructPar; md5sum 3e-09/p > ../p3
qEnd 4e-9; tryt 280 "parallel restart to 4e-9 over the reconstructed times" mpirun -np 2 cellBlastFoam -parallel; cont
tryt 120 "reconstructPar -newTimes" reconstructPar -newTimes; ls -d [0-9]* | tr '\n' ' '; echo; md5sum -c ../p3 2>&1 | tail -1
