#!/bin/bash
# a18 (class 3, our other tools on a case WHILE cellBlastFoam runs in it): a blast (planeWaveInflow top, iblast) run to 6 ns in the background; once 1e-09 is written: planeWave -inflow (the same wave), solidToFoam solid/solid.h5, cellMesh, sweepCase (an entry of the case), setRiemannProblem are refused naming the run (the lock)? Then the run itself: finished rc 0, its results whole (times, solid.h5 steps = solid.xmf's)?
. "$(dirname "$0")/../lib.sh"
iblast; iEnd 6e-9; cellBlastFoam > log.first 2>&1 & p=$!; waitFor 120 test -f 1e-09/.writeCommitted; echo "   running: $(lockOf | cut -c1-80)"; sums > ../s0
tryf "planeWave -inflow (the same wave)" planeWave $IW
tryf "solidToFoam solid/solid.h5" solidToFoam solid/solid.h5
tryf "cellMesh" cellMesh
tryf "sweepCase" sweepCase -case . -entry constant/fsiProperties/coupling/solidSubcycles -values "2" -run cellBlastFoam -output "x=log.cellBlastFoam:/End(.*)/"
tryf "setRiemannProblem" setRiemannProblem
wait $p; echo "   the run: rc=$? times $(ls -d [1-9]* | tr '\n' ' '); solid.h5 $(h5steps solid/solid.h5) steps, solid.xmf $(xmfsteps solid/solid.xmf); constant/: $(ls constant | tr '\n' ' ')"
