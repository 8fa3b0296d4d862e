#!/bin/bash
# x09: two Allruns of different tutorials in ONE folder: the indentation Allrun (fine steps) running, then the sod verification Allrun (copied in as Allrun.sod with its system files renamed away: it would run blockMesh, setRiemannProblem) started there: refused by the lock before it touches anything?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp $ROOT/tutorials/verification/sodIdealGas/Allrun Allrun.sod
./Allrun > log.a1 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; ls > ../before
run 60 ./Allrun.sod > ../log.sod 2>&1; head -4 ../log.sod | cut -c1-250; ls > ../after; diff ../before ../after && echo "no file added or removed"
wait $p; echo "Allrun exit $?"; tail -1 log.a1
