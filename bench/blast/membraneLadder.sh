#!/bin/bash
# The blast preview's mesh ladder with the membrane refined across its
# 200 nm thickness along with the rest (issue 17 item 4; not a test;
# docs/results/blastPlaneWave.md, "The ladder across the membrane's
# thickness").
#
#   bench/blast/membraneLadder.sh OUT [-j N] PULSE:xF:LN ...
#
# Each PULSE:xF:LN (e.g. 15:x0.35:L4) is one run of bench/blast/
# knobMatrix.py (variant base) of the preview with a PULSE ns pulse to
# 90 ns, every size scaled by F as bench/blast/analysis/patchLadder.py's
# levels (-h 0.25F um -far F um -dz 0.25F um -cell 0.5F um: the membrane
# 0.4F um along its interfaces) and N elements across the membrane
# (-membraneLayers N: 200/N nm), -solidSubcycles 4 on every level: the
# coupled step is the water's Courant step (the solid sub-steps; in lock
# step the membrane's thin elements would set it: with N = 4 at F = 0.35
# their stable step is 1.8e-11 s against the water's 2.6e-11 s). A ladder with one refinement ratio r in
# every direction keeps F*N fixed: x1.4:L1, x0.7:L2, x0.35:L4 (r = 2) or
# x1:L1, x0.5:L2, x0.25:L4. The case of PULSE:xF:LN is
# OUT/xFLN_PULSEns/base_PULSEns/axisymmetricPreview (patchLadder.py's
# LABEL=CASE: xFLN=that folder). Runs -j N at a time (default 2) in the
# order given (give the finest first: it takes longest), each niced (10);
# a finished case is kept (knobMatrix --keep). Prints one line per run.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 2 ] || { echo "usage: ${0##*/} OUT [-j N] PULSE:xF:LN ..." >&2; exit 1; }
out=$1; shift
jobs=2
if [ "${1:-}" = -j ]
then
    [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] \
        || { echo "${0##*/}: -j ${2:-}: a whole number >= 1" >&2; exit 1; }
    jobs=$2; shift 2
fi
for level in "$@"
do
    [[ "$level" =~ ^[0-9.]+:x[0-9.]+:L[1-8]$ ]] || {
        echo "${0##*/}: $level: PULSE:xF:LN (PULSE [ns], F the size" \
             "factor, N in 1..8 the membrane's layers)" >&2; exit 1; }
done
mkdir -p "$out"

one() {
    local pulse f n label
    IFS=: read -r pulse f n <<< "$1"
    f=${f#x} n=${n#L}
    label=x${f}L${n}_${pulse}ns
    # sizes [m] from the factor (awk: no rounding of the product's digits)
    read -r h far cell ps <<< "$(awk -v f="$f" -v p="$pulse" \
        'BEGIN { printf "%.6g %.6g %.6g %.6g", 0.25e-6*f, 1e-6*f, 0.5e-6*f, p*1e-9 }')"
    echo "$(date -u +%H:%M:%S) start $label"
    nice -n 10 "$here/knobMatrix.py" --jobs 1 --keep --variants base \
        --pulses "$ps" --out "$out/$label" -- -h "$h" -far "$far" \
        -dz "$h" -cell "$cell" -membraneLayers "$n" -solidSubcycles 4 -endTime 9e-8 \
        > "$out/$label.log" 2>&1
    local rc=$?
    local c=$out/$label/base_${pulse}ns/axisymmetricPreview
    echo "$(date -u +%H:%M:%S) end $label (exit $rc): $(grep -h "^CPU time of the time loop" \
        "$c/log.cellBlastFoam" 2>/dev/null || echo "no CPU line: see $out/$label.log")"
}
export -f one
export here out
printf '%s\n' "$@" | xargs -P "$jobs" -I{} bash -c 'one "$@"' _ {}
