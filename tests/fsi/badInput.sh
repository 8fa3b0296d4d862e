#!/bin/bash
# Input errors of cellBlastFoam: an unknown coupling scheme lists the valid
# ones; a solid interface that does not overlap the fluid patch is an
# error naming the gap; solidSubcycles outside [1, 1000] or not an
# integer is an error naming the entry and the range. A bad coupling
# entry is refused before any output is created (adv37 w98: refused after
# solid/solid.h5, solid.xmf and postProcessing were written, and the
# corrected run then refused as one over results).
set -uo pipefail
dir=$(cd "$(dirname "$0")" && pwd)
. "$dir/../../etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
run()
{
    rm -rf "$work/case"; cp -r "$dir/pulseLayer" "$work/case"
    (cd "$work/case" && eval "$1" && blockMesh > /dev/null 2>&1 \
        && cellBlastFoam > log 2>&1)
    if [ $? -eq 0 ]; then echo "FAIL: '$1' was accepted"; fail=1; return; fi
    if ! grep -q "$2" "$work/case/log"; then
        echo "FAIL: '$1': no message '$2'"; tail -20 "$work/case/log"; fail=1
    else
        echo "ok: $2"
    fi
}
run "sed -i 's/^\( *scheme *\)robin;/\1secant;/' constant/fsiProperties" \
    "entry 'scheme' in 'coupling' = 'secant' is not one of the valid values"
run "sed -i 's/^\( *scheme *\)robin;/\1secant;/' constant/fsiProperties" \
    "IQNILS"
run "sed -i 's/min         (50e-6/min         (60e-6/; s/max         (100e-6/max         (110e-6/' constant/solidProperties" \
    "lie off the solid interface (no"
run "sed -i 's/fluidPatch      interface;/fluidPatch      wall;/' constant/fsiProperties" \
    "is not a patch of the fluid"
run "sed -i 's/^\( *scheme *robin;\)/\1 solidSubcycles 0;/' constant/fsiProperties" \
    "entry 'solidSubcycles' = 0 is outside the valid range \[1, 1000\]"
run "sed -i 's/^\( *scheme *robin;\)/\1 solidSubcycles 2.5;/' constant/fsiProperties" \
    "entry 'solidSubcycles' = '2.5' is not an integer"
# nothingWritten EDIT MESSAGE: refused as run() requires, and the case has
# no solid/ and no postProcessing/ (a fresh case: nothing to write over)
nothingWritten()
{
    run "$1" "$2"
    local made
    made=$(cd "$work/case" && ls -d solid postProcessing 2>/dev/null | tr '\n' ' ')
    if [ -n "$made" ]; then
        echo "FAIL: '$1': the refused run created $made"; fail=1
    else
        echo "ok: nothing written by the refused run ($2)"
    fi
}
nothingWritten "sed -i 's/^\( *maxIter *\)30;/\10;/' constant/fsiProperties" \
    "entry 'maxIter' = 0 is outside the valid range"
nothingWritten "sed -i 's/^\( *tolerance *\)1e-6;/\1-1;/' constant/fsiProperties" \
    "entry 'tolerance' = -1 is outside the valid range"
nothingWritten "sed -i 's/^\( *onNonConvergence *\)warn;/\1ignore;/' constant/fsiProperties" \
    "entry 'onNonConvergence' in 'coupling' = 'ignore' is not one of the valid values (warn stop)"
exit $fail
