#!/bin/bash
# The 3D quarter's von Mises after the pulse (issue 17 item 6) under
# settings that Allrun has no option for: as bench/blast/restLadder.sh
# quarter3D, with dictionary edits after `Allrun -noRun` and an optional
# pulse amplitude; not a test (docs/results/blast3D.md, "What makes the
# rest flow in 3D").
#
#   bench/blast/restVariants3D.sh DIR LABEL "ALLRUN OPTIONS" "EDITS" \
#                                 [LABEL "OPTIONS" "EDITS" ...]
#
# EDITS: space-separated items, each
#   FILE:ENTRY=VALUE   foamDictionary -entry ENTRY -set VALUE FILE in the
#                      prepared case (e.g. constant/fsiProperties:
#                      interface/load=mappedForces); a comma in VALUE
#                      stands for a space (system/fvSchemes:
#                      interpolationSchemes/reconstruct(U)=
#                      normalTangential,MUSCL,upwind)
#   amplitude=PA       the pulse's 50 MPa replaced by PA in 0.orig/p (and
#                      in the Allrun's pulse edit) before Allrun
#   membrane=water     the membrane's quadratic law (paper eq. 2) replaced
#                      by water's Mie-Grueneisen law, as nucleus and
#                      cytoplasm have: the transparent cell, whose exact
#                      answer is the 1D plane wave, at rest after it
# For each setting DIR/LABEL holds the case; prints the time loop's CPU,
# the planeWave -check lines of the solid probes and its FAIL lines (each
# case its own 1D answer: the amplitude may differ). Niced (10), one run
# at a time.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
. "$root/etc/scratchFolder"
[ $# -ge 4 ] || { echo "usage: $0 DIR LABEL \"OPTIONS\" \"EDITS\" ..." >&2; exit 1; }
dir=$1; shift
mkdir -p "$dir"
while [ $# -ge 3 ]
do
    label=$1 opts=$2 edits=$3; shift 3
    case=$dir/$label
    echo "== quarter3D $label: $opts; edits: ${edits:-none}"
    scratchFolder restVariants3D.sh "$case" @case     # never a user's (adv51 n01)
    cp -r "$root/tutorials/blast/quarter3D/"{0.orig,constant,system,Allrun} "$case/"
    ok=yes
    for e in $edits
    do
        case $e in
        amplitude=*)
            a=${e#amplitude=}
            sed -i "s/5e7/$a/" "$case/0.orig/p" "$case/Allrun" ;;
        esac
    done
    # shellcheck disable=SC2086
    (cd "$case" && ./Allrun $opts -noRun -noPlots) > "$dir/$label.log" 2>&1 \
        || { echo "   Allrun failed: $dir/$label.log"; continue; }
    for e in $edits
    do
        case $e in
        amplitude=*) ;;
        membrane=water)
            python3 -m neuronFsi.membraneLaw water \
                "$case/constant/solidProperties" || ok=no ;;
        *:*=*)
            file=${e%%:*} rest=${e#*:}
            value=${rest#*=}
            foamDictionary -entry "${rest%%=*}" -set "${value//,/ }" \
                "$case/$file" > /dev/null || ok=no ;;
        *) echo "   bad edit $e"; ok=no ;;
        esac
    done
    [ $ok = yes ] || continue
    (cd "$case" && nice -n 10 cellBlastFoam > log.cellBlastFoam 2>&1)
    grep -h "^CPU time of the time loop" "$case/log.cellBlastFoam" \
        || { echo "   run failed: $case/log.cellBlastFoam"; tail -5 "$case/log.cellBlastFoam"; continue; }
    planeWave -case "$case" -check > "$dir/$label.check" 2>&1
    grep -E "^solid_[0-9] |^solid_p[0-9] |FAIL" "$dir/$label.check"
done
