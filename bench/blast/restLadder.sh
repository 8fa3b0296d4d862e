#!/bin/bash
# The Fig. 10 point's von Mises and strain after the pulse (issue 17 item
# 6) against the scene's resolution: the preview (tests/blast/
# runPreview.sh) or the 3D quarter (tutorials/blast/quarter3D/Allrun),
# one run per setting, 5 ns pulse to 150 ns; not a test
# (docs/results/blast3D.md, "The von Mises at rest in 3D").
#
#   bench/blast/restLadder.sh preview|quarter3D DIR LABEL "ALLRUN OPTIONS" \
#                             [LABEL "OPTIONS" ...]
#
# For each setting DIR/LABEL holds the case; prints its planeWave -check
# measures of the solid probes (rest strain and von Mises; the pressure
# errors) and the CPU time of the time loop with its split
# (log.cellBlastFoam). Niced (10), one run at a time. The settings of one
# DIR must share the pulse, the column and the probes' heights (the first
# run's 1D answer, DIR/reference.dat, is reused).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/etc/bashrc"
. "$root/etc/scratchFolder"
kind=$1 dir=$2; shift 2
mkdir -p "$dir"
# a setting whose run fails is said and the others run; the script's exit
# status then says so too (adv51 n01: exit 0 after "run failed")
failed=0 settings=0 failedLogs=""
while [ $# -ge 2 ]
do
    settings=$((settings + 1))
    label=$1 opts=$2; shift 2
    case=$dir/$label
    echo "== $kind $label: $opts"
    if [ "$kind" = preview ]
    then
        # shellcheck disable=SC2086
        nice -n 10 "$root/tests/blast/runPreview.sh" "$case" -pulse 5e-9 \
            $opts -noPlots -noVTK > "$dir/$label.log" 2>&1
        run=$case/axisymmetricPreview
    else
        scratchFolder restLadder.sh "$case" @case
        cp -r "$root/tutorials/blast/quarter3D/"{0.orig,constant,system,Allrun} "$case/"
        # shellcheck disable=SC2086
        (cd "$case" && ./Allrun $opts -noRun -noPlots \
            && nice -n 10 cellBlastFoam > log.cellBlastFoam 2>&1) \
            > "$dir/$label.log" 2>&1
        run=$case
    fi
    grep -h "^CPU time of the time loop" "$run/log.cellBlastFoam" \
        || { echo "   run failed: $dir/$label.log"; tail -5 "$dir/$label.log"
             failed=$((failed + 1)) failedLogs="$failedLogs $dir/$label.log"
             continue; }
    # the 1D answer once per DIR (the same pulse, column and probe
    # heights for every setting): planeWave -reference reuses it
    ref=()
    [ -f "$dir/reference.dat" ] && ref=(-reference "$dir/reference.dat")
    planeWave -case "$run" -check "${ref[@]}" > "$dir/$label.check" 2>&1
    [ -f "$dir/reference.dat" ] \
        || cp "$run/postProcessing/planeWave/reference.dat" "$dir/"
    grep -E "^solid_[0-9] |^solid_p[0-9] |FAIL" "$dir/$label.check"
done
if [ $failed -gt 0 ]
then
    echo "restLadder.sh: $failed of $settings setting(s) failed:$failedLogs" >&2
    exit 1
fi
