#!/bin/bash
# CASETIMEOUT=900
# u13 (fix19i row "the preview's default -inflow named as such", varied: the quarter's default -inflow (20e-6 when -box >
# 30e-6) and the other check of the water's top, one axial cell above the inner box): (a) quarter3D ./Allrun -box 32e-6
# -dz 8e-6 (no -inflow: 20e-6 by default, below 12.4e-6 + dz) -noRun; (b) the preview -Z 14e-6 -dz 2e-6 without -inflow
# (default 14.4e-6 > -Z); (c) the preview -Z 16e-6 -dz 1e-6 -inflow 13e-6 (given, below 12.4e-6 + dz); (d) quarter3D
# -box 25e-6 -inflow 20e-6 -dz 8e-6. Expected: each refused before meshing, naming the option, saying for (a), (b) that the
# value is the default and what to give; a default named as if the user gave it = UNCLEAR (low); a mesh run first and
# only its error = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
qa() { rm -rf $W/q; cp -r $ROOT/tutorials/blast/quarter3D $W/q; cd $W/q; ./Allclean > /dev/null 2>&1; tryt 400 "$1" ./Allrun -np 2 -h 1e-6 -lateral 2e-6 -far 5e-6 -endTime 2e-9 -noPlots -noRun "${@:2}"; echo "   said: $(grep -a -i 'error\|refus' $W/try.log | head -3 | tr '\n' '|' | cut -c1-400) | meshed: $(ls constant/*.msh 2>/dev/null | tr '\n' ' ') $(ls log.cellMesh* 2>/dev/null | tr '\n' ' ')"; }
pa() { rm -rf $W/c; prev; tryt 300 "$1" ./Allrun -h 0.5e-6 -far 4e-6 -cell 1e-6 -endTime 2e-9 -noPlots -noVTK -noRun "${@:2}"; echo "   said: $(grep -a -i 'error\|refus' $W/try.log | head -3 | tr '\n' '|' | cut -c1-400) | meshed: $(ls constant/*.msh 2>/dev/null | tr '\n' ' ') $(ls log.cellMesh* 2>/dev/null | tr '\n' ' ')"; }
qa "(a) quarter -box 32e-6 -dz 8e-6, -inflow not given" -box 32e-6 -dz 8e-6
pa "(b) preview -Z 14e-6 -dz 2e-6, -inflow not given" -Z 14e-6 -dz 2e-6
pa "(c) preview -Z 16e-6 -dz 1e-6 -inflow 13e-6" -Z 16e-6 -dz 1e-6 -inflow 13e-6
qa "(d) quarter -box 25e-6 -inflow 20e-6 -dz 8e-6" -box 25e-6 -inflow 20e-6 -dz 8e-6
