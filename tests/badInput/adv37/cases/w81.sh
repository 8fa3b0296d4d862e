#!/bin/bash
# w81: blast tutorial Allrun started inside a SYMLINKED path of the case while cellBlastFoam runs by hand in the real path: refused (one case, two paths)?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/axisymmetricPreview" $W/real; ln -s $W/real $W/link; cd $W/real; ./Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK -noRun > log.prep 2>&1; echo "prep rc=$?"
printf 'endTime 8e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun; cellBlastFoam > log.hand 2>&1 & p=$!; sleep 1.5
cd $W/link; timeout -s KILL 120 ./Allrun -h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 1e-9 -noPlots -noVTK > $W/log.allrun 2>&1; echo "Allrun via the link rc=$?"; grep -a -i -m3 "use\|lock\|refus\|fatal" $W/log.allrun | cut -c1-250
wait $p; echo "hand run rc=$?"; tail -1 $W/real/log.hand
