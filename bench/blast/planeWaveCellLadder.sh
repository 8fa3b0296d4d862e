#!/bin/bash
# The solid alone under the exact 1D answer of the blast (5 ns, 50 MPa, the
# tutorials' water and pulse), r-z and 3D cells at equal element sizes
# (issue 17 item 6; docs/results/blast3D.md, "The von Mises at rest in
# 3D"); not a test.
#
#   bench/blast/planeWaveCellLadder.sh DIR [-rz "1.4 0.7 0.35"]
#                                          [-3d "1.4 0.7"] [-- OPTIONS]
#
# 1. DIR/wave5ns.dat: the 1D column of tutorials/blast/quarter3D (its
#    water law and pulse, the 100 um column, 25 nm cells) probed every 50
#    nm up to 8.4 um, to 150 ns (bench/blast/planeWaveTable.py; kept);
# 2. per size [um]: the preview's cell (cellMesh mode axisymmetric,
#    tutorials/blast/axisymmetricPreview's cellMeshDict, sizes as its
#    Allrun -cell: membrane 0.8, contact 0.8) and the quarter's (quarter3D's
#    cellMeshDict without its fluid, membrane 5/7);
# 3. planeWaveCell with -table DIR/wave5ns.dat -absorbing -textFactor4
#    -shearViscosity 0.2 -filter -vonMises -every 1e-9 (the tutorials'
#    solid settings) and OPTIONS, to 150 ns; its log DIR/rz_H.log,
#    DIR/3d_H.log; then bench/blast/planeWaveCellSummary.py of them.
# Niced (10), one run at a time.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
dir=$1; shift
rz="1.4 0.7 0.35" d3="1.4 0.7" extra=()
while [ $# -gt 0 ]
do
    case $1 in
        -rz) rz=$2; shift 2 ;;
        -3d) d3=$2; shift 2 ;;
        --) shift; extra=("$@"); break ;;
        *) echo "planeWaveCellLadder.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
. "$root/etc/scratchFolder"
exe=$root/build/bin/planeWaveCell
[ -x "$exe" ] || { echo "no $exe: cmake --build build --target planeWaveCell" >&2; exit 1; }
mkdir -p "$dir"
if [ ! -f "$dir/wave5ns.dat" ]
then
    scratchFolder planeWaveCellLadder.sh "$dir/column" @case   # adv51 n01
    cp -r "$root/tutorials/blast/quarter3D/"{0.orig,constant,system} "$dir/column/"
    nice -n 10 /usr/bin/python3 "$here/planeWaveTable.py" "$dir/column" \
        "$dir/wave5ns.dat" --endTime 150e-9 || exit 1
fi
logs=()
mesh()
{
    local kind=$1 h=$2 case=$dir/mesh_$1_$2 dict membrane
    [ -f "$case/constant/cell.msh" ] && return 0
    mkdir -p "$case/system" "$case/constant"
    if [ "$kind" = rz ]
    then
        dict=$root/tutorials/blast/axisymmetricPreview/system/cellMeshDict
        membrane=$(/usr/bin/python3 -c "print($h*0.8)")
    else
        dict=$root/tutorials/blast/quarter3D/system/cellMeshDict
        membrane=$(/usr/bin/python3 -c "print($h*5/7)")
    fi
    cp "$dict" "$case/system/cellMeshDict"
    [ "$kind" = 3d ] && foamDictionary -entry fluid -remove \
        "$case/system/cellMeshDict" > /dev/null
    for e in "nucleusSize ${h}e-6" "cytoplasmSize ${h}e-6" \
             "membraneSize ${membrane}e-6"
    do
        foamDictionary -entry "${e% *}" -set "${e#* }" \
            "$case/system/cellMeshDict" > /dev/null
    done
    [ "$kind" = rz ] && foamDictionary -entry contactSize \
        -set "${membrane}e-6" "$case/system/cellMeshDict" > /dev/null
    cellMesh -case "$case" > "$case/log.cellMesh" 2>&1 \
        || { echo "cellMesh failed: $case/log.cellMesh" >&2; return 1; }
}
for kind in rz 3d
do
    sizes=$rz; [ $kind = 3d ] && sizes=$d3
    for h in $sizes
    do
        mesh $kind "$h" || exit 1
        log=$dir/${kind}_$h.log
        /usr/bin/time -f "%U s CPU" -o "$log.time" nice -n 10 "$exe" \
            "$dir/mesh_${kind}_$h/constant/cell.msh" 150e-9 50e6 1e-9 5e-9 \
            -table "$dir/wave5ns.dat" -absorbing -textFactor4 \
            -shearViscosity 0.2 -filter -vonMises -every 1e-9 \
            "${extra[@]}" > "$log" || { echo "failed: $log" >&2; exit 1; }
        echo "$log: $(cat "$log.time")"
        logs+=("$log")
    done
done
/usr/bin/python3 "$here/planeWaveCellSummary.py" "${logs[@]}"
