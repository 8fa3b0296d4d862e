#!/bin/bash
# The solid alone under the exact plane-wave traction (issue 17 item 4;
# docs/results/blastPlaneWave.md, "The solid alone under the exact
# traction"): bench/solid/exactTraction.py's 1D table (the tutorial's
# water and 5 ns pulse, neuronFsi.layeredColumn in cells of 20 nm) on the
# driver's block (r in [0, 4] um, z in [0, 7.9] um, cytoplasm, loaded on
# its top and side), aligned and random meshes of 0.35, 0.25, 0.175 um,
# the tutorial's solid settings, to 90 ns; tests/blast/
# checkExactTraction.py asserts the exact answer's uniaxial strain on the
# aligned meshes (the lateral strain small and falling at order >= 1) and
# that the measure sees the irregular meshes' lateral strain (about 1.5e-3
# at every size). About 11 s CPU.
# Usage: exactTraction.sh <exactTraction executable>
set -uo pipefail
exe=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$root/bench/solid/exactTraction.py" \
    "$root/tutorials/blast/axisymmetricPreview" "$work/tab" -top 7.9e-6 \
    -dz 20e-9 -probes "$root/tests/blast/exactTraction.probes" \
    || { echo "FAIL exactTraction.py"; exit 1; }
for kind in aligned random
do
    for h in 0.35 0.25 0.175
    do
        d=$work/$kind-$h
        mkdir -p "$d"
        cp -r "$work/tab/constant" "$work/tab/postProcessing" "$d/"
        "$exe" "block:4e-6:7.9e-6:${h}e-6:$kind" "$work/tab/table.dat" "$d" \
            -probes "$work/tab/probes" -fields 6.6e-8,7e-8 > "$d.log" \
            || { echo "FAIL exactTraction $kind $h"; cat "$d.log"; exit 1; }
        tail -1 "$d.log"
    done
done
/usr/bin/python3 "$root/tests/blast/checkExactTraction.py" "$work"
