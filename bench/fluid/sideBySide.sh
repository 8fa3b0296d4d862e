#!/bin/bash
#------------------------------------------------------------------------------
# sideBySide.sh OLD NEW CASE... : the same cases run by the solvers of two
# built checkouts of this project, interleaved (old, new, old, new, ...), so
# that a change of the fluid kernel is timed under the same machine load.
#   OLD, NEW  project directories, each built with ./Allwmake
#   CASE      prepared case directories (mesh, 0/), e.g. the Sod cases of
#             bench/fluid/run.py --out DIR (DIR/cost/3D_rhoRiemannFoam_SSPRK3)
# Options (before OLD): -n N repetitions (default 3), -a APP (rhoRiemannFoam)
# Prints per case and checkout the least CPU time per step [ms] of the time
# loop after the first step (ExecutionTime, as run.py), and new/old.
#------------------------------------------------------------------------------
set -euo pipefail
n=3
app=rhoRiemannFoam
while [ "$#" -gt 0 ]
do
    case "$1" in
        -n) n=$2; shift 2 ;;
        -a) app=$2; shift 2 ;;
        *) break ;;
    esac
done
[ "$#" -ge 3 ] || { sed -n 3,11p "$0" >&2; exit 1; }
old=$(cd "$1" && pwd); new=$(cd "$2" && pwd); shift 2

# CPU time per step [ms] of one run of the solver of checkout $1 on case
# $2, in a fresh copy of the case's 0, constant and system (the end time is
# always written: a second run in the case itself would compute nothing)
perStep() {
    (
        . "$1/etc/bashrc"
        run=$(mktemp -d)
        trap 'rm -rf "$run"' EXIT
        cp -r "$2/0" "$2/constant" "$2/system" "$run"
        cd "$run"
        "$app" > log 2>&1 || { tail -20 log >&2; exit 1; }
        awk '/^ExecutionTime/ { t[n++] = $3 }
            END {
                if (n < 2) { print "fewer than 2 steps timed" > "/dev/stderr"; exit 1 }
                printf "%.3f\n", 1e3*(t[n-1] - t[0])/(n - 1)
            }' log
    )
}

printf '%-60s %10s %10s %8s\n' case "old [ms]" "new [ms]" new/old
for c in "$@"
do
    bestOld=""; bestNew=""
    for _ in $(seq "$n")
    do
        o=$(perStep "$old" "$c"); w=$(perStep "$new" "$c")
        bestOld=$(printf '%s\n%s\n' "$o" "$bestOld" | sed '/^$/d' | sort -g | head -1)
        bestNew=$(printf '%s\n%s\n' "$w" "$bestNew" | sed '/^$/d' | sort -g | head -1)
    done
    printf '%-60s %10s %10s %8.3f\n' "$c" "$bestOld" "$bestNew" \
        "$(echo "$bestNew / $bestOld" | bc -l)"
done
