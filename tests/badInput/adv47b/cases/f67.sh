#!/bin/bash
# f67 (class 3, planeWave -inflow -overwrite and cellMesh on a running case): the finished preview restarted to 6e-9 in the background; beside it planeWave -inflow 14e-6 -overwrite (it would write constant/inflowWave, an input of the run) and cellMesh: each refused naming the run (lock), constant/ unchanged; the run ends rc 0.
. "$(dirname "$0")/../lib.sh"
bd; blastEnd 6e-9 1e-9; latest; md5sum constant/* 2>/dev/null > ../c0; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -d 3e-09
tryt 120 "planeWave -inflow during the run" planeWave -inflow 14e-6 -overwrite; tryt 60 "cellMesh during the run" cellMesh
wait $p; echo "   run rc=$?"; md5sum -c ../c0 2>&1 | grep -v ': OK' | head -3; ls constant | tr '\n' ' '; echo
