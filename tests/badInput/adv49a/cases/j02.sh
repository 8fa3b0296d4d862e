#!/bin/bash
# CASETIMEOUT=900
# j02 (class 5, checkRestartState varied in a processor directory only): the finished 2-rank preview pbd, startFrom
# latestTime, endTime 3e-9, `mpirun -np 2 cellBlastFoam -parallel -acceptEdited`: (a) processor1/2e-09/rho[5] NaN (rank 1
# only), (b) processor0/2e-09/rhoE[3] -1e308 (rank 0 only), (c) processor1/2e-09/rho[5] 1e-290, (d) both ranks: rank 0
# rhoU[0] 1e300 and rank 1 rho[7] -1, (e) processor1's rho, its processor patch value[0] NaN (the boundary field only),
# (f) the 3D quarter on 2 ranks (q): processor1/2e-09/rho[5] NaN with -acceptEdited. Each refused on every rank at once
# (rc 1, no hang: 120 s) naming the rank's file, the cell and why; never a signal, never a run from the state.
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 120 "$l" mpirun -np 2 cellBlastFoam -parallel "$@"; echo "   sig lines: $(sig) | times p1: $(ls -d processor1/[0-9]* 2>/dev/null | tr '\n' ' ')"; echo "   msg: $(msg 6)"; cd $W; rm -rf pblast; cp -a keep pblast; cd pblast; }
setb processor1/2e-09/rho 5 nan; one "(a) processor1 rho[5] NaN" -acceptEdited
setb processor0/2e-09/rhoE 3 -1e308; one "(b) processor0 rhoE[3] -1e308" -acceptEdited
setb processor1/2e-09/rho 5 1e-290; one "(c) processor1 rho[5] 1e-290" -acceptEdited
setb processor0/2e-09/rhoU 0 1e300; setb processor1/2e-09/rho 7 -1; one "(d) rank 0 rhoU[0] 1e300, rank 1 rho[7] -1" -acceptEdited
setbb processor1/2e-09/rho procBoundary1to0 0 nan; one "(e) processor1 rho procBoundary1to0 value[0] NaN" -acceptEdited
cd $W; q; latest; qEnd 3e-9; rm -f .runLock; setb processor1/2e-09/rho 5 nan
tryt 300 "(f) 3D quarter processor1 rho[5] NaN" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; echo "   sig lines: $(sig) | times p1: $(ls -d processor1/[0-9]* | tr '\n' ' ')"; echo "   msg: $(msg 6)"
