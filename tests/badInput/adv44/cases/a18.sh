#!/bin/bash
# a18 (class 3, our other tools on a case WHILE cellBlastFoam runs in it): a blast with a planeWaveInflow top (iblast, its wave to 31 ns) run to 30 ns in the background; once 1e-09 is written: planeWave -inflow -overwrite (the same wave), solidToFoam solid/solid.h5, cellMesh, sweepCase (an entry of the case), setRiemannProblem: each refused naming the run (the lock), nothing changed? Then the run itself (SIGTERMed once the tools are done): its results whole (times, solid.h5 steps = solid.xmf's), constant/ unchanged?
. "$(dirname "$0")/../lib.sh"
iblast 30e-9; cellBlastFoam > log.first 2>&1 & p=$!; waitFor 120 test -f 1e-09/.writeCommitted; echo "   running: $(lockOf | cut -c1-80)"; find constant system 0 -type f | sort | xargs md5sum > ../c0
tryf "planeWave -inflow -overwrite (the same wave)" planeWave $IW -overwrite
tryf "solidToFoam solid/solid.h5" solidToFoam solid/solid.h5
tryf "cellMesh" cellMesh
tryf "sweepCase" sweepCase -case . -entry constant/fsiProperties/coupling/solidSubcycles -values "2" -run cellBlastFoam -output "x=log.cellBlastFoam:/End(.*)/"
tryf "setRiemannProblem" setRiemannProblem
echo "   the run still going: $(kill -0 $p 2>/dev/null && echo yes || echo NO), at $(ls -d [1-9]* | tail -1); constant/system/0 changed: $(md5sum -c --quiet ../c0 2>&1 | tr '\n' ' ')"
kill -TERM $p; wait $p; echo "   the run: rc=$? (SIGTERM) times $(ls -d [1-9]* | tr '\n' ' '); solid.h5 $(h5steps solid/solid.h5) steps, solid.xmf $(xmfsteps solid/solid.xmf)"
