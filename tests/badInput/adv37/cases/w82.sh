#!/bin/bash
# w82: blast tutorial Allrun (a copy, small options) while a cellBlastFoam started by hand runs in it: the Allrun refused before it changes anything (mesh, 0/, logs)?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/c; cd $W/c; ./Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK -noRun > log.prep 2>&1; echo "prep rc=$?"
printf 'endTime 8e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun; md5sum constant/polyMesh/points constant/cell.msh 0/p > ../m; cellBlastFoam > log.hand 2>&1 & p=$!; sleep 1.5
timeout -s KILL 120 ./Allrun -h 0.3e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK > ../log.allrun 2>&1; echo "Allrun rc=$?"; grep -a -i -m3 "use\|lock\|refus\|fatal" ../log.allrun | cut -c1-250
md5sum -c ../m | grep -v ": OK" ; wait $p; echo "hand run rc=$?"; tail -1 log.hand
