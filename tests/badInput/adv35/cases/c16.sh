#!/bin/bash
# c16: two blast Allruns at once in one fresh copy (same options, -endTime 2e-9 -noPlots -noVTK)
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/two"; cd "$W/two"; for f in 0.orig constant system Allrun; do cp -r "$ROOT/tutorials/blast/axisymmetricPreview/$f" .; done
opts="-h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK"
./Allrun $opts > ../a.log 2>&1 & p=$!; sleep 0.3; ./Allrun $opts > ../b.log 2>&1; echo "second rc=$?"; tail -3 ../b.log | cut -c1-200; wait $p; echo "first rc=$?"; tail -2 ../a.log | cut -c1-200
ls; ls -a 2e-09 2>/dev/null | head; h5ls solid/solid.h5/steps 2>&1 | head -4
cellBlastFoam -postProcess > /dev/null 2>&1; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; cellBlastFoam > log.check 2>&1; echo "restart after both: rc=$?"; grep -A2 FATAL log.check | head -3
