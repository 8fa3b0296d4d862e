#!/bin/bash
# exactTractionRuns.sh OUT SCENE_c07 SCENE_c05 SCENE_c035: the runs of
# docs/results/blastPlaneWave.md, "The solid alone under the exact
# traction" (issue 17 item 4; not a test). SCENE_*: the coupled runs of
# the transparent cell at -cell 0.35 / 0.25 / 0.175 um with bench/blast/
# ballProbes.override (docs: "von Mises at a point", section 3; their
# constant/cell.msh and solidProbes header give the mesh and the probes).
# In OUT:
#   c07, c05, c035       bench/solid/exactTraction.py's 1D table (10 nm)
#                        and build/bin/exactTraction at the defaults
#   LEVEL-VARIANT        one setting changed (VARIANTS below)
#   c035-t20             the table in cells of 20 nm
#   blk-KIND-H[-V]       the driver's block (r 4 um, z 7.9 um), KIND
#                        aligned / smooth / random, H 0.35 ... 0.125 um
#                        (random also with gaussPoints, gp, and without
#                        the shear viscosity, sv0)
#   blk-randomF-H        random meshes with nodes moved by up to F h, F =
#                        0.0625, 0.125, 0.25, H 0.35 and 0.175 um
# Every run writes fields at 66, 70 and 90 ns. About 2 min CPU.
set -euo pipefail
[ $# -eq 4 ] || { sed -n 2,20p "$0"; exit 1; }
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
exe=$root/build/bin/exactTraction
py=/usr/bin/python3
out=$1; shift
declare -A scene=([c07]=$1 [c05]=$2 [c035]=$3)
fields=6.6e-8,7e-8,9e-8
# cellMsh SCENE: a scene's cell mesh (the run's case or its folder)
cellMsh() {
    if [ -f "$1/constant/cell.msh" ]
    then
        echo "$1/constant/cell.msh"
    else
        echo "$1/axisymmetricPreview/constant/cell.msh"
    fi
}
# run DIR MESH TABLEDIR PROBES [options]: the driver into DIR with
# TABLEDIR's reference and solidProperties (for ballLadder.py)
run() {
    local d=$1 mesh=$2 tab=$3 probes=$4
    shift 4
    mkdir -p "$d"
    if [ "$d" != "$tab" ]
    then
        rm -rf "$d/constant" "$d/postProcessing"
        cp -r "$tab/constant" "$d/"
        mkdir -p "$d/postProcessing"
        cp -r "$tab/postProcessing/planeWave" "$d/postProcessing/"
    fi
    nice -n 10 "$exe" "$mesh" "$tab/table.dat" "$d" -probes "$probes" \
        -fields $fields "$@" | tail -1 | cut -c1-160
}
VARIANTS=("sv0 -shearViscosity 0" "hg0 -hourglass 0" "b1z -b1 0"
    "b2h -b2 0.6" "one -oneMaterial cytoplasm"
    "gp -volumetric gaussPoints" "gp0 -volumetric gaussPoints -hourglass 0"
    "fs1 -faceSamples 1" "fs16 -faceSamples 16" "sm20 -smooth 20")
for l in c07 c05 c035
do
    s=${scene[$l]}
    nice -n 10 $py "$root/bench/solid/exactTraction.py" "$s" "$out/$l"
    mesh=$(cellMsh "$s")
    run "$out/$l" "$mesh" "$out/$l" "$out/$l/probes"
    for v in "${VARIANTS[@]}"
    do
        set -- $v
        name=$1; shift
        run "$out/$l-$name" "$mesh" "$out/$l" "$out/$l/probes" "$@"
    done
done
mesh=$(cellMsh "${scene[c035]}")
nice -n 10 $py "$root/bench/solid/exactTraction.py" "${scene[c035]}" \
    "$out/c035-t20" -dz 20e-9
run "$out/c035-t20" "$mesh" "$out/c035-t20" "$out/c035-t20/probes"
for kind in aligned smooth random
do
    for h in 0.35 0.25 0.175 0.125
    do
        run "$out/blk-$kind-$h" "block:4e-6:7.9e-6:${h}e-6:$kind" "$out/c07" \
            "$root/tests/blast/exactTraction.probes"
    done
done
for h in 0.35 0.25 0.175 0.125
do
    run "$out/blk-random-$h-gp" "block:4e-6:7.9e-6:${h}e-6:random" \
        "$out/c07" "$root/tests/blast/exactTraction.probes" \
        -volumetric gaussPoints
    run "$out/blk-random-$h-sv0" "block:4e-6:7.9e-6:${h}e-6:random" \
        "$out/c07" "$root/tests/blast/exactTraction.probes" \
        -shearViscosity 0
done
for f in 0.0625 0.125 0.25
do
    for h in 0.35 0.175
    do
        run "$out/blk-random$f-$h" "block:4e-6:7.9e-6:${h}e-6:random:$f" \
            "$out/c07" "$root/tests/blast/exactTraction.probes"
    done
done
