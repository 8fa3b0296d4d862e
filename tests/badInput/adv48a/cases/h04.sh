#!/bin/bash
# CASETIMEOUT=900
# h04 (class 5, adv47a f08 (b) varied, 2 ranks): the preview decomposed (pblastDone), startFrom latestTime, endTime 3e-9:
# (a) processor0/2e-09/rhoE[3] -1, (b) processor1/2e-09/rho[7] NaN, (c) processor1/2e-09/rho cut to half, (d)
# processor0/2e-09/uniform/inputDigests emptied, (e) processor1/2e-09/.writeCommitted removed (processor0's intact);
# the 3D quarter (adv47b's qBase, 2 ranks, 2e-09 committed), endTime 3e-9: (f) processor0/2e-09/rho 64 B zeroed, (g)
# processor1/2e-09/rhoU[10] NaN. Each refused naming the rank's file (or the time moved aside on both ranks); never a
# sigFpe/abort on a rank, never a hang (the other rank waiting), never a run from it.
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; rm -f .runLock; cp -a . ../pkeep
one_() { local l=$1 d=$2 k=$3; tryt 120 "$l" mpirun -np 2 cellBlastFoam -parallel; echo "   sig lines: $(sig) | times p0: $(ls -d processor0/[0-9]* processor0/*incomplete* 2>/dev/null | tr '\n' ' ')| p1: $(ls -d processor1/[0-9]* processor1/*incomplete* 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf $d; cp -a $k $d; cd $d; }
setb processor0/2e-09/rhoE 3 -1; one_ "(a) processor0 rhoE[3] -1" blast pkeep
setb processor1/2e-09/rho 7 nan; one_ "(b) processor1 rho[7] NaN" blast pkeep
cutf processor1/2e-09/rho 50; one_ "(c) processor1 rho cut" blast pkeep
: > processor0/2e-09/uniform/inputDigests; one_ "(d) processor0 inputDigests emptied" blast pkeep
rm processor1/2e-09/.writeCommitted; one_ "(e) processor1 marker removed" blast pkeep
cd $W; q; qEnd 3e-9; latest; rm -f .runLock; cp -a . ../qkeep; ls -d processor0/[0-9]* | tr '\n' ' '; echo
dmgf processor0/2e-09/rho; one_ "(f) 3D quarter processor0 rho 64 B zeroed" q qkeep
setb processor1/2e-09/rhoU 10 nan; one_ "(g) 3D quarter processor1 rhoU[10] NaN" q qkeep
