#!/bin/bash
#------------------------------------------------------------------------------
# pulseLayerMotion.sh [OUT] [REPEATS] [BAND]: issue 18 item 2 in 1D (not a
# test). The 1D pulse through a layer onto a wall (tests/fsi/pulseLayer, as
# it is: dynamicMotionSolverFvMesh + displacementLaplacian, a global solve
# per coupling pass) against the same case with the band motion of the
# blast scenes (fsiProperties interface/motionDistance BAND, default 5e-6 m;
# staticFvMesh: no motion solver), run one after the other REPEATS times
# (default 2). Prints per run cellBlastFoam's CPU split of the time loop
# (mesh motion / whole loop) and analysePulseLayer.py's measures, so the
# share and the results are compared side by side.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
. "$root/etc/scratchFolder"
out=${1:-${TMPDIR:-/tmp}/pulseLayerMotion.$$}
repeats=${2:-2}
band=${3:-5e-6}
mkdir -p "$out"
src=$root/tests/fsi/pulseLayer

prepare()  # prepare DIR VARIANT
{
    scratchFolder pulseLayerMotion.sh "$1" @case    # never a user's (adv51 n01)
    cp -r "$src/." "$1/"
    if [ "$2" = band ]
    then
        sed -i "s/^\( *mapTolerance .*\)$/\1\n    motionDistance  $band;/" \
            "$1/constant/fsiProperties"
        grep -q "motionDistance" "$1/constant/fsiProperties" \
            || { echo "pulseLayerMotion.sh: could not set motionDistance" >&2; exit 1; }
        sed -i 's/^dynamicFvMesh .*/dynamicFvMesh       staticFvMesh;/' \
            "$1/constant/dynamicMeshDict"
    fi
    (cd "$1" && blockMesh > log.blockMesh 2>&1)
}

for variant in laplacian band
do
    prepare "$out/$variant.mesh" "$variant"
done
printf '%-9s %-3s %-12s %-14s %-10s %s\n' variant run "loop [s]" \
    "motion [s]" "share [%]" measures
for i in $(seq 1 "$repeats")
do
    for variant in laplacian band
    do
        d=$out/$variant.$i
        scratchFolder pulseLayerMotion.sh "$d" @case
        cp -r "$out/$variant.mesh/." "$d/"
        (cd "$d" && cellBlastFoam > log.cellBlastFoam 2>&1) \
            || { echo "pulseLayerMotion.sh: $d failed" >&2; exit 1; }
        line=$(grep "^CPU time of the time loop" "$d/log.cellBlastFoam")
        loop=$(sed 's/.*time loop \([0-9.e+-]*\) s.*/\1/' <<< "$line")
        motion=$(sed 's/.*mesh motion \([0-9.e+-]*\) s.*/\1/' <<< "$line")
        share=$(awk -v m="$motion" -v l="$loop" 'BEGIN {printf "%.1f", 100*m/l}')
        printf '%-9s %-3s %-12s %-14s %-10s %s\n' "$variant" "$i" "$loop" \
            "$motion" "$share" \
            "$(/usr/bin/python3 "$root/tests/fsi/analysePulseLayer.py" "$d" 1000)"
    done
done
