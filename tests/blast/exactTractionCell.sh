#!/bin/bash
# The preview's cell alone under the exact plane-wave traction on its
# structured r-z mesh (issue 17 item 4; docs/results/blastPlaneWave.md, "A
# structured r-z cell"): cellMesh's meshType structured and unstructured
# (gmsh) at -cell 0.35 and 0.175 um (nucleusSize = cytoplasmSize = CELL,
# membraneSize 0.8 CELL, the tutorial's other entries), bench/solid/
# exactTraction.py's 1D table (the tutorial's water and 5 ns pulse, 20 nm
# cells), the driver to 90 ns with the preview's Fig. 10 point (bench/
# solid/cellProbes.py); tests/blast/checkExactTractionCell.py asserts
# that the lateral strain falls with h on the structured mesh and not on
# gmsh's, and the Fig. 10 point's von Mises on the structured mesh. About
# 20 s CPU.
# Usage: exactTractionCell.sh <exactTraction executable>
set -uo pipefail
exe=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tut=$root/tutorials/blast/axisymmetricPreview
for t in structured unstructured
do
    for c in 0.35 0.175
    do
        m=$work/mesh-$t-$c
        mkdir -p "$m/system" "$m/constant"
        cp "$tut/system/cellMeshDict" "$tut/system/controlDict" "$m/system/"
        mem=$(/usr/bin/python3 -c "print('%.6g' % (0.8*$c))")
        printf '%s\n' "meshType $t;" "nucleusSize ${c}e-6;" \
            "cytoplasmSize ${c}e-6;" "membraneSize ${mem}e-6;" \
            "contactSize ${mem}e-6;" > "$m/system/cellMeshDict.allrun"
        cellMesh -case "$m" > "$m/log" 2>&1 \
            || { echo "FAIL cellMesh $t $c"; tail -20 "$m/log"; exit 1; }
        /usr/bin/python3 "$root/bench/solid/cellProbes.py" \
            "$m/constant/cell.msh" "$m/probes" \
            || { echo "FAIL cellProbes.py $t $c"; exit 1; }
    done
done
/usr/bin/python3 "$root/bench/solid/exactTraction.py" "$tut" "$work/tab" \
    -top 7.9e-6 -dz 20e-9 -probes "$work/mesh-structured-0.35/probes" \
    || { echo "FAIL exactTraction.py"; exit 1; }
for t in structured unstructured
do
    for c in 0.35 0.175
    do
        d=$work/$t-$c
        mkdir -p "$d"
        cp -r "$work/tab/constant" "$work/tab/postProcessing" "$d/"
        "$exe" "$work/mesh-$t-$c/constant/cell.msh" "$work/tab/table.dat" \
            "$d" -probes "$work/mesh-$t-$c/probes" -fields 6.6e-8,7e-8 \
            > "$d.log" \
            || { echo "FAIL exactTraction $t $c"; cat "$d.log"; exit 1; }
        tail -1 "$d.log"
    done
done
/usr/bin/python3 "$root/tests/blast/checkExactTractionCell.py" "$work"
