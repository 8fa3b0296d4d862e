#!/bin/bash
# v71: Allrun locks: the blast preview's Allrun running (endTime 2e-8) while planeWave, planeWave -partial and sweepCase are started on the case
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/two"; cd "$W/two"; for f in 0.orig constant system Allrun; do cp -r "$ROOT/tutorials/blast/axisymmetricPreview/$f" .; done
opts="-h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-8 -writeInterval 1e-9 -noPlots -noVTK"
setsid ./Allrun $opts > ../a.log 2>&1 & p=$!; for i in $(seq 100); do [ -f log.cellBlastFoam ] && break; sleep 0.2; done; sleep 1
planeWave -dz 50e-9 > ../pw1.log 2>&1; echo "planeWave rc=$?"; grep -a -i "error" ../pw1.log | head -1 | cut -c1-250
planeWave -partial -dz 50e-9 > ../pw2.log 2>&1; echo "planeWave -partial rc=$?"; head -1 ../pw2.log | cut -c1-250
sweepCase -entry system/controlDict/maxCo -values 0.5,0.6 -output postProcessing/fsi/0/coupling.dat > ../sw.log 2>&1; echo "sweepCase rc=$?"; grep -a -i "error\|use" ../sw.log | head -2 | cut -c1-250
wait $p; echo "Allrun rc=$?"; tail -1 ../a.log | cut -c1-200
