#!/bin/bash
#------------------------------------------------------------------------------
# bench/ciTime/fuzzCompileCost.sh OUT [NAME...]: the CPU of compiling each
# source of
# the fuzz build's solid library (tests/fuzz/project: clang++, libFuzzer
# coverage, ASan + UBSan, -O2 -g), one after the other, nice -n 10,
# ccache not used; prints "seconds file" per source (user + system) and the
# total. NAMEs (e.g. ExplicitSolver): those sources only, in that order.
# Object files in OUT.
#------------------------------------------------------------------------------
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 OUT [NAME...]" >&2; exit 1; }
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$1; shift
sources=()
if [ $# -eq 0 ]
then
    for f in core materials elements model loads contact io drivers
    do
        sources+=("$root/src/solid/$f"/*.C)
    done
else
    for n in "$@"
    do
        s=""
        for f in core materials elements model loads contact io drivers
        do
            [ -f "$root/src/solid/$f/$n.C" ] && s=$root/src/solid/$f/$n.C
        done
        [ -n "$s" ] || { echo "fuzzCompileCost: no source $n.C in src/solid" >&2; exit 1; }
        sources+=("$s")
    done
fi
mkdir -p "$out"
inc=()
for f in core materials elements model loads contact io drivers
do
    inc+=(-I"$root/src/solid/$f")
done
inc+=(-I"$root/src/eos" -I/usr/include/hdf5/serial -I"$root/src/foamTools"
      -isystem /usr/include/eigen3)
echo "fuzzCompileCost: start $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
for s in "${sources[@]}"
do
    f=$(basename "$(dirname "$s")")
    {
        /usr/bin/time -f "%U %S" -o "$out/t" nice -n 10 /usr/bin/clang++ \
            -O2 -g -DNDEBUG -fsanitize=address,undefined \
            -fno-sanitize-recover=undefined -fno-omit-frame-pointer \
            -fsanitize=fuzzer-no-link -std=gnu++17 "${inc[@]}" \
            -c "$s" -o "$out/$(basename "$s").o"
        awk -v s="$f/$(basename "$s")" '{ printf "%7.2f s %s\n", $1 + $2, s }' "$out/t"
    }
done | tee "$out/costs"
awk '{ t += $1 } END { printf "%7.2f s total\n", t }' "$out/costs"
echo "fuzzCompileCost: end $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
