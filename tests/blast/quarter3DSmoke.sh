#!/bin/bash
# Smoke run of tutorials/blast/quarter3D (its default hexahedral water:
# 0.5 um along z, 1 um across near the cell, first layer 0.6 um at the
# cell, 2 um far; cell 1.4 um: membrane faces 1 um; a 30 um water cube:
# small, so that the pulse reaches the cell at 14.6 ns, and holding the
# default inner box of the O-grid, 3.95 um around the cell (L/2 > 12.35
# um); to 18.2 ns), the water ending at 15 um (Allrun -inflow 15e-6: a
# planeWaveInflow top lets in the 1D wave of the full 30 um column there,
# constant/inflowWave from planeWave -inflow; 10,849 water cells instead
# of 17,599, time loop 18.6 s CPU instead of 27.4 s, the arrival at the
# probe 0.05 % from the expected one instead of 1.3 %): the whole Allrun
# chain (cellMesh quarter3D cell and
# box, gmshToFoam with symmetry planes, the inflow top and its wave,
# cellBlastFoam with robin coupling, foamToVTK, solidToFoam + foamToVTK
# -region solid).
# Asserts (checkQuarter3D.py): the force map is conservative (1e-12) and
# the unit-pressure force equals the projected areas of the quarter cell
# (1 %); the pulse reaches the probe (cytoplasm-nucleus interface, 75 %
# of the nucleus height) at 0.05 ns + (L - z_probe)/Us within 3 %; every
# coupling step converged, no NaN; fluid and solid VTK files exist; the
# fluid points of the symmetry planes and the substrate are exactly on
# them at the end.
# usage: quarter3DSmoke.sh [atRest|refineCell]
#   atRest: to 2 ns only (the chain and the interface at rest before the
#   pulse's precursor reaches the cell; checkQuarter3D.py --atRest)
#   refineCell: atRest with the water along the cell refined (Allrun
#   -refineCell, -h doubled), on 2 ranks (the sectors' processor patches
#   cut through the refined cells and their split-face neighbours): also
#   the interface faces four times cellMesh's, split-face polyhedra,
#   checkMesh clean
set -euo pipefail
mode=${1:-arrival}
L=30e-6
endTime=1.82e-8
h=(-h 0.6e-6)
[ "$mode" = arrival ] || endTime=2e-9
[ "$mode" = refineCell ] && h=(-h 1.2e-6 -refineCell 1.2e-6 -np 2)
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
work=${TMPDIR:-/tmp}/quarter3DSmoke.$$
trap 'rm -rf "$work" "$work.log"' EXIT
mkdir -p "$work/quarter3D"
src=$here/../../tutorials/blast
for f in 0.orig constant system Allrun
do
    cp -r "$src/quarter3D/$f" "$work/quarter3D/"
done
case=$work/quarter3D
# Writes at half the end time and at the end (the moved mesh after the
# arrival for the plane check of checkQuarter3D.py)
foamDictionary -entry writeInterval -set "$(/usr/bin/python3 -c "print($endTime/2)")" \
    "$case/system/controlDict" > /dev/null
rm -rf "$case/constant/polyMesh" "$case"/constant/*.msh
PROJECT_DIR=$here/../.. "$case/Allrun" -box $L "${h[@]}" -far 2e-6 \
    -growth 5e-6 -cell 1.4e-6 -endTime $endTime -inflow 15e-6 -noPlots \
    > "$work.log" 2>&1 || { cat "$work.log"; exit 1; }
ls "$case"/VTK/*.vtm > /dev/null
ls "$case"/VTK/solid > /dev/null
/usr/bin/python3 "$here/checkQuarter3D.py" "$case" $L "$mode"
# The tutorial's pictures (Fig. 10 curves, interface maxima, the cell with
# a quarter cut away at the write nearest 65.5 ns)
/usr/bin/python3 "$src/plotBlast.py" "$case" > "$work.log" 2>&1 \
    || { cat "$work.log"; exit 1; }
for png in fig10 interfaceMaxima snapshot65.5ns
do
    [ -s "$case/$png.png" ] || { echo "FAIL: no $png.png"; exit 1; }
done
