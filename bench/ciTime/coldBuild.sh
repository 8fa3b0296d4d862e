#!/bin/bash
#------------------------------------------------------------------------------
# bench/ciTime/coldBuild.sh DIR [-j N]: the cold build CI does, timed by part.
# Clones this checkout's HEAD into DIR (git clone --shared: a clean tree, no
# build products), then, with ccache disabled (CCACHE_DISABLE=1) and
# nice -n 10, runs ./Allwmake and the fuzz build of the test fuzz.build
# (tests/fuzz/run -build). Prints, per part, the wall time and the CPU
# (user + system of the finished child processes, from /proc/PID/stat of
# Allwmake at each of its '==' headers) and the load average.
#------------------------------------------------------------------------------
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 DIR [-j N]" >&2; exit 1; }
dir=$1; shift
jobs=2
[ "${1:-}" = -j ] && jobs=$2
[ -e "$dir" ] && { echo "coldBuild: $dir exists (give a new folder)" >&2; exit 1; }
src=$(cd "$(dirname "$0")/../.." && pwd)
git clone -q --shared "$src" "$dir"
git -C "$dir" checkout -q "$(git -C "$src" rev-parse HEAD)"
cd "$dir"
export CCACHE_DISABLE=1
tick=$(getconf CLK_TCK)
now() { date +%s.%N; }
echo "coldBuild: $(git rev-parse --short HEAD) in $dir, -j $jobs, load $(cut -d' ' -f1-3 /proc/loadavg)"
# Allwmake in the background, its output read line by line: at each header
# the CPU of the children it has waited for so far
start=$(now)
coproc AW { exec nice -n 10 ./Allwmake -j "$jobs" 2>&1; }
pid=$AW_PID
cpu() { awk -v t="$tick" '{ printf "%.1f", ($16 + $17) / t }' "/proc/$pid/stat" 2>/dev/null || echo "?"; }
lastT=$start lastC=0 part="(start)"
report() {
    local t c
    t=$(now); c=$1
    awk -v p="$part" -v w="$(awk -v a="$lastT" -v b="$t" 'BEGIN{print b-a}')" \
        -v c="$c" -v l="$lastC" -v ld="$(cut -d' ' -f1 /proc/loadavg)" \
        'BEGIN{ printf "  %-60s wall %7.1f s  CPU %7.1f s  (load %s)\n", p, w, c-l, ld }'
    lastT=$t lastC=$c
}
while IFS= read -r line <&"${AW[0]}"
do
    echo "$line" >> "$dir.allwmake.log"
    case "$line" in
        "== "*) c=$(cpu); [ "$part" != "(start)" ] && report "$c"; part=${line#== } ;;
    esac
done
# the children of Allwmake's last part: read before it is reaped is not
# possible; take the total from bash's times of this shell instead
wait "$pid" || { echo "coldBuild: Allwmake failed (log $dir.allwmake.log)"; exit 1; }
total=$(times | tail -1 | awk '{ split($1,a,"m"); split($2,b,"m"); print a[1]*60 + a[2] + b[1]*60 + b[2] }')
report "$total"
echo "  Allwmake total: wall $(awk -v a="$start" -v b="$(now)" 'BEGIN{printf "%.1f", b-a}') s, CPU $total s"
part="fuzz build (tests/fuzz/run -build, clang++)"
. etc/bashrc
c0=$total
/usr/bin/time -f "%e %U %S" -o "$dir.fuzz.time" nice -n 10 env CXX_FUZZ=/usr/bin/clang++ \
    WM_NCOMPPROCS=$jobs bash tests/fuzz/run -build > "$dir.fuzz.log" 2>&1
read -r fw fu fs < "$dir.fuzz.time"
echo "  $part wall $fw s  CPU $(awk -v u="$fu" -v s="$fs" 'BEGIN{print u+s}') s (load $(cut -d' ' -f1 /proc/loadavg))"
echo "coldBuild: done, load $(cut -d' ' -f1-3 /proc/loadavg)"
