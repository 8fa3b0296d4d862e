#!/bin/bash
# CASETIMEOUT=900
# o02 (fix19h's -inflow checked before meshing, adv50b k48, varied: other bad values, a default -inflow that falls outside,
# -inflow below the cell): a fresh copy of tutorials/blast/axisymmetricPreview, `./Allrun -noRun` with the small sizes
# (-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6) and (a) -inflow 0, (b) -inflow -1e-6, (c) -inflow nan, (d) -inflow inf,
# (e) -Z 20e-6 -inflow 20e-6 (equal), (f) -Z 31e-6 -dz 20e-6 (the default -inflow max(14e-6, 12.4e-6+dz) = 32.4e-6 > Z),
# (g) -inflow 3e-6 (below the cell's top), (h) -inflow 1e-300; quarter3D (-noRun, its smoke sizes): (i) -inflow 0,
# (j) -inflow 2e-6 (below the cell: documented as checked by cellMesh). Each: refused rc 1 naming -inflow and the range
# before anything is meshed (no constant/polyMesh, cell.msh, log.cellMesh, 0/), or accepted with a case that runs.
. "$(dirname "$0")/../lib.sh"
T=$ROOT/tutorials/blast
st() { echo "   left: $(ls -d constant/polyMesh constant/cell.msh constant/fluid.msh log.cellMesh* log.blockMesh* log.fluidWedgeMesh* 0 constant/inflowWave log.planeWave* 2>/dev/null | tr '\n' ' ')"; echo "   said: $(grep -a -h -m2 -i 'error\|refus\|outside\|valid' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-400)"; }
pv() { cd $W; rm -rf p; cp -r $T/axisymmetricPreview p; cd p; tryt 400 "$1" ./Allrun -noRun -noPlots -noVTK -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 "${@:2}"; st; }
pv "(a) -inflow 0" -inflow 0
pv "(b) -inflow -1e-6" -inflow -1e-6
pv "(c) -inflow nan" -inflow nan
pv "(d) -inflow inf" -inflow inf
pv "(e) -Z 20e-6 -inflow 20e-6" -Z 20e-6 -inflow 20e-6
pv "(f) -Z 31e-6 -dz 20e-6 (default -inflow above Z)" -Z 31e-6 -dz 20e-6
pv "(g) -inflow 3e-6 (below the cell's top)" -inflow 3e-6
pv "(h) -inflow 1e-300" -inflow 1e-300
qv() { cd $W; rm -rf q; cp -r $T/quarter3D q; cd q; tryt 600 "$1" ./Allrun -noRun -noPlots -box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -cell 1.4e-6 "${@:2}"; st; }
qv "(i) quarter3D -inflow 0" -inflow 0
qv "(j) quarter3D -inflow 2e-6 (below the cell)" -inflow 2e-6
