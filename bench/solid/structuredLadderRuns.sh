#!/bin/bash
# structuredLadderRuns.sh OUT [CELL ...]: the runs of docs/results/
# blastPlaneWave.md, "A structured r-z cell" (issue 17 item 4; not a
# test): the solid alone under the exact plane-wave traction (build/bin/
# exactTraction, as "The solid alone under the exact traction") on the
# preview's cell meshed by cellMesh with meshType structured and, side by
# side, unstructured (gmsh), at the sizes CELL [m] (default 0.35e-6
# 0.25e-6 0.175e-6 0.125e-6; nucleusSize = cytoplasmSize = CELL,
# membraneSize = contactSize = 0.8 CELL, as the preview's Allrun -cell).
# In OUT:
#   tab                   bench/solid/exactTraction.py's 1D table of the
#                         tutorial's water and 5 ns pulse (10 nm cells)
#   mesh-TYPE-CELL        the cellMesh case (system/cellMeshDict.allrun,
#                         constant/cell.msh, log.cellMesh)
#   TYPE-CELL             the driver's run (probes: bench/solid/
#                         cellProbes.py on that mesh), fields at 66, 70,
#                         90 ns
#   structured-CELL-V     one setting of the driver changed on the
#                         structured mesh: sm20 (-smooth 20) at every
#                         CELL; sm500 (-smooth 500) and one (-oneMaterial
#                         cytoplasm) at 0.35e-6 and 0.175e-6 if given
# Then bench/solid/exactTractionLadder.py CELL=OUT/structured-CELL ...
# About 3 min CPU with the default sizes.
# Environment (default: the runs above):
#   TYPES="structured unstructured"  the meshes; smooth: meshType
#                         structured with structuredSmoothing elliptic
#                         (docs: "A map smooth across the nucleus surface")
#   VARIANTS=1            0: no variant runs
#   PROBE_OPTIONS=""      more options of bench/solid/cellProbes.py (e.g.
#                         "-along 5e-8,4 -normal 2.5e-8,5e-8,1e-7")
set -euo pipefail
[ $# -ge 1 ] || { sed -n 2,20p "$0"; exit 1; }
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
. "$root/etc/scratchFolder"
exe=$root/build/bin/exactTraction
py=/usr/bin/python3
out=$1; shift
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(0.35e-6 0.25e-6 0.175e-6 0.125e-6)
tut=$root/tutorials/blast/axisymmetricPreview
mkdir -p "$out"
# mesh TYPE CELL: the cell mesh into OUT/mesh-TYPE-CELL
mesh() {
    local d=$out/mesh-$1-$2
    scratchFolder structuredLadderRuns.sh "$d"   # never a user's (adv51 n01)
    mkdir -p "$d/system" "$d/constant"
    cp "$tut/system/cellMeshDict" "$tut/system/controlDict" "$d/system/"
    local m
    m=$($py -c "import sys; print('%.10g' % (0.8*float(sys.argv[1])))" "$2")
    case $1 in
        smooth) printf '%s\n' "meshType structured;" \
            "structuredSmoothing elliptic;" ;;
        *) printf '%s\n' "meshType $1;" ;;
    esac > "$d/system/cellMeshDict.allrun"
    printf '%s\n' "nucleusSize $2;" "cytoplasmSize $2;" \
        "membraneSize $m;" "contactSize $m;" >> "$d/system/cellMeshDict.allrun"
    nice -n 10 cellMesh -case "$d" > "$d/log.cellMesh" 2>&1 \
        || { tail -20 "$d/log.cellMesh"; exit 1; }
    grep -E "^Structured|^Interior|^structuredSmoothing|^    total" \
        "$d/log.cellMesh" || true
}
first=""
for c in "${sizes[@]}"
do
    for t in ${TYPES:-structured unstructured}
    do
        echo "== $t $c m"
        mesh $t "$c"
        d=$out/$t-$c
        scratchFolder structuredLadderRuns.sh "$d"
        mkdir -p "$d"
        # shellcheck disable=SC2086
        $py "$root/bench/solid/cellProbes.py" "$out/mesh-$t-$c/constant/cell.msh" \
            "$d/probes" ${PROBE_OPTIONS:-}
        if [ -z "$first" ]
        then
            # the 1D table once: its reference.dat depends on the probes'
            # heights only, the same on every mesh
            nice -n 10 $py "$root/bench/solid/exactTraction.py" "$tut" \
                "$out/tab" -top 7.9e-6 -probes "$d/probes"
            first=$d
        fi
        cp -r "$out/tab/constant" "$out/tab/postProcessing" "$d/"
        nice -n 10 "$exe" "$out/mesh-$t-$c/constant/cell.msh" \
            "$out/tab/table.dat" "$d" -probes "$d/probes" \
            -fields 6.6e-8,7e-8,9e-8 > "$d/log" 2>&1 \
            || { tail -5 "$d/log"; exit 1; }
        tail -1 "$d/log" | cut -c1-160
    done
done
# run DIR MESH PROBES [options]: a variant on a mesh made above
variant() {
    local d=$1 m=$2 probes=$3
    shift 3
    scratchFolder structuredLadderRuns.sh "$d"   # never a user's (adv51 n01)
    mkdir -p "$d"
    cp -r "$out/tab/constant" "$out/tab/postProcessing" "$d/"
    nice -n 10 "$exe" "$m" "$out/tab/table.dat" "$d" -probes "$probes" \
        -fields 6.6e-8,7e-8,9e-8 "$@" > "$d/log" 2>&1 \
        || { tail -5 "$d/log"; exit 1; }
    tail -1 "$d/log" | cut -c1-160
}
[ "${VARIANTS:-1}" = 1 ] || exit 0
for c in "${sizes[@]}"
do
    m=$out/mesh-structured-$c/constant/cell.msh
    p=$out/structured-$c/probes
    echo "== structured $c m, variants"
    variant "$out/structured-$c-sm20" "$m" "$p" -smooth 20
    case $c in
        0.35e-6|0.175e-6)
            variant "$out/structured-$c-sm500" "$m" "$p" -smooth 500
            variant "$out/structured-$c-one" "$m" "$p" -oneMaterial cytoplasm
            ;;
    esac
done
