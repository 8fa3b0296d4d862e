#!/bin/bash
# Hexahedral against tetrahedral water of tutorials/blast/quarter3D (issue
# 18 item 1; not a test). In scratch copies of the tutorial (inputs only),
# Allrun -noRun prepares each variant, then cellBlastFoam runs on one rank:
#
#   bench/blast/hexWater.sh cost [endTime [binDir]]   (default 2e-9 s)
#       tet  : Allrun -tet (the tetrahedral box of earlier versions)
#       hex  : Allrun (the hexahedral default: dz 0.5 um, lateral 1 um)
#       with binDir, also
#       hex of binDir : the same with the cellMesh of binDir (e.g. one
#              built from an earlier commit: its O-grid against this one;
#              the solver is this tree's in every variant); the two
#              hexahedral variants then run at the same time (2 cores)
#     per variant: fluid cells, the smallest water edge (cellMesh's
#     quality table), checkMesh's largest non-orthogonality, skewness and
#     aspect ratio, time steps to endTime, the last time step,
#     cellBlastFoam's CPU split of the time loop (before the pulse reaches
#     the cell: one coupling pass per step, the step set by the sound
#     speed, so it is the step of the run until the arrival)
#   bench/blast/hexWater.sh column [endTime]    (default 4e-8 s)
#       Allrun -lateral 2e-6 -far 10e-6 (the default's 0.5 um along z and
#       at the cell, coarser across the column: 42,070 cells), then
#       planeWave -probes fluid -endTime <the last probe time>: the water
#       probes (axis and x = y = 25 um) against the 1D plane wave
#
# Every variant with the whole 100 um water column (Allrun -inflow none:
# the figures of docs/results/blast3D.md were measured so; the shortened
# column: bench/blast/inflow3D.sh).
# The scratch folders are kept (printed) for inspection.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
. "$root/etc/bashrc"
what=${1:-cost}

prepare() {     # prepare <dir> <Allrun options...>
    local c=$1/quarter3D
    shift
    python3 -m neuronFsi.scratch "$root/tutorials/blast/quarter3D" "$c" \
        0.orig constant system Allrun --ignore polyMesh '*.msh'
    (cd "$c" && PROJECT_DIR=$root ./Allrun -noRun -noPlots -inflow none "$@" \
        > log.prepare 2>&1) || { tail -20 "$c/log.prepare"; exit 1; }
    echo "$c"
}

run() {         # run <case> <endTime>
    (cd "$1" && foamDictionary -entry writeInterval -set "$2" \
        system/controlDict > /dev/null \
     && cellBlastFoam > log.cellBlastFoam 2>&1) \
        || { tail -20 "$1/log.cellBlastFoam"; exit 1; }
}

summary() {     # summary <name> <case>
    local c=$2
    printf '%s: %s cells, smallest edge %s m, %s; %s steps, last deltaT %s s; %s\n' "$1" \
        "$(awk '/^ *cells:/ {print $2}' "$c/log.checkMesh")" \
        "$(awk '$1 == "water" && NF == 7 {print $3}' "$c/log.cellMesh")" \
        "$(awk '/non-orthogonality Max:/ {n = $4} /Max skewness/ {s = $4}
                /Max aspect ratio/ {a = $5}
                END {printf "non-orthogonality %s deg, skewness %s, aspect ratio %s", n, s, a}' \
            "$c/log.checkMesh")" \
        "$(grep -c '^Time =' "$c/log.cellBlastFoam")" \
        "$(awk '/^deltaT =/ {d = $3} END {print d}' "$c/log.cellBlastFoam")" \
        "$(grep '^CPU time of the time loop' "$c/log.cellBlastFoam")"
}

work=$(mktemp -d /tmp/hexWater.XXXXXX)
case $what in
cost)
    T=${2:-2e-9}
    other=${3:-}
    tet=$(prepare "$work/tet" -tet -endTime "$T")
    hex=$(prepare "$work/hex" -endTime "$T")
    if [ -n "$other" ]
    then
        [ -x "$other/cellMesh" ] || { echo "no $other/cellMesh" >&2; exit 1; }
        old=$(PATH=$(cd "$other" && pwd):$PATH prepare "$work/hexOther" \
            -endTime "$T")
    fi
    run "$tet" "$T"
    if [ -n "$other" ]
    then
        # The two hexahedral variants at the same time: on a shared
        # machine they then see the same load (one after the other, the
        # same runs differed by 20 % in CPU per step)
        run "$hex" "$T" & h=$!
        run "$old" "$T" & o=$!
        wait $h && wait $o || exit 1
    else
        run "$hex" "$T"
    fi
    summary tetrahedra "$tet"
    summary hexahedra "$hex"
    [ -z "$other" ] || summary "hexahedra, cellMesh of $other" "$old"
    ;;
column)
    T=${2:-4e-8}
    c=$(prepare "$work/column" -lateral 2e-6 -far 10e-6 -endTime "$T")
    run "$c" "$T"
    summary "hexahedra, lateral 2 um, far 10 um" "$c"
    last=$(tail -1 "$c"/postProcessing/fluidProbes/0/p | awk '{print $1}')
    (cd "$c" && planeWave -probes fluid -endTime "$last")
    ;;
*)
    echo "usage: hexWater.sh cost [endTime [binDir]] | column [endTime]" >&2; exit 1 ;;
esac
echo "scratch: $work"
