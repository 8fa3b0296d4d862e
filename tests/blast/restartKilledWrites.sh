#!/bin/bash
# Kills of cellBlastFoam during its writes lose nothing (issue 8;
# src/foamTools/writeGuard.H, atomic solid.h5). The preview on the short
# water column of restart.sh, to 16 ns, writing every 5 steps (46 writes
# since the solver's faster steps: with every 10 steps, 23 writes, the six
# stops could use them all up when the timed kills land between writes,
# and the last start ended before its kill (Alltest 2026-12-06);
# each write: fluid fields and points, the solid step in solid/solid.h5 and the solid
# and coupling states under <time>/uniform):
#  (a) run uninterrupted;
#  (b) a copy stopped and continued from its latest time (startFrom
#      latestTime) until it ends: SIGKILL and SIGTERM at arbitrary instants
#      (8 and 16 writes in), then four kills timed while a time directory
#      is being written (a write takes 2-40 ms, median 12 ms: SIGKILL and
#      SIGTERM as soon as .writeInProgress appears, SIGKILL 4 ms and 8 ms
#      later). After each stop every file of every
#      committed time is recorded; at the end none may have changed;
#  (c) a copy of (a) cut back to a write whose solid step and state are
#      written but whose coupling state is not (what a kill after the solid
#      step leaves), with the later steps still in solid.h5: continued, the
#      time is moved aside and the later steps removed from solid.h5.
# Asserted for (b) and (c): every file of every time directory of (a)
# byte-equal (fluid fields, points, solid and coupling states), solid.h5
# with the same steps and bitwise-equal datasets, solid.xmf byte-equal, the
# logs bitwise equal (compareRestart.py: the coupling log complete); for
# (b) at least one kill inside a write (a time moved aside at the restart).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib/restartTools.sh"

bash "$here/shortColumn.sh" "$work/ref" writeControl timeStep \
    writeInterval 5 startFrom latestTime
ref=$work/ref/axisymmetricPreview
cp -r "$ref" "$work/killed"
cp -r "$ref" "$work/cut"

# (a)
t0=$(date +%s%N)
(cd "$ref" && cellBlastFoam > log.cellBlastFoam 2>&1) \
    || { tail -20 "$ref/log.cellBlastFoam"; exit 1; }
times=($(foamListTimes -case "$ref"))
for t in "${times[@]}"
do
    [ -f "$ref/$t/.writeCommitted" ] \
        || { echo "restartKilledWrites: $t has no commit marker"; exit 1; }
done
echo "restartKilledWrites: (a) ${#times[@]} writes in" \
    "$(( ($(date +%s%N) - t0)/1000000 )) ms, solid.h5" \
    "$(( $(stat -c %s "$ref/solid/solid.h5")/1024 )) kB"

# Same results as (a): every time directory of (a) from $2 on, solid.h5,
# solid.xmf and the logs
sameAsReference()
{
    local case=$1 t status=0
    for t in "${times[@]}"
    do
        if awk -v t="$t" -v t0="$2" 'BEGIN{exit !(t < t0)}'; then continue; fi
        sameFiles "$ref/$t" "$case/$t" \
            $(cd "$ref/$t" && find . -type f ! -name .writeCommitted) \
            || status=1
    done
    cmp "$ref/solid/solid.xmf" "$case/solid/solid.xmf" || status=1
    /usr/bin/python3 "$here/compareRestart.py" "$ref" "$case" --bitwise \
        --h5 || status=1
    return $status
}

# (b)
cd "$work/killed"
# Built-ins only: polled without pause while the solver runs
committed()   # number of committed time directories
{
    local m=([0-9]*/.writeCommitted)
    [ -e "${m[0]}" ] && echo ${#m[@]} || echo 0
}
writing()   # more than $1 committed, and a time directory being written
{
    local m=([0-9]*/.writeCommitted) w
    [ -e "${m[0]}" ] && [ ${#m[@]} -gt $1 ] || return 1
    for w in [0-9]*/.writeInProgress
    do
        case $w in *.incomplete*) ;; *) [ -e "$w" ] && return 0 ;; esac
    done
    return 1
}
stopped()   # what the stop interrupted, and the committed files recorded
{
    local d phase="between writes"
    for d in [0-9]*/.writeInProgress
    do
        d=${d%/.writeInProgress}
        case $d in *.incomplete*|'[0-9]*') continue ;; esac
        if [ -f "$d/uniform/solidState" ]
        then
            phase="inside the write of $d, after its solid state"
        elif [ solid/solid.h5 -nt "$d/.writeInProgress" ]
        then
            phase="inside the write of $d, after its solid.h5 step"
        elif [ solid/solid.h5.tmp -nt "$d/.writeInProgress" ]
        then
            phase="inside the write of $d, in its solid.h5 step"
        else
            phase="inside the write of $d, in its fluid fields"
        fi
    done
    echo "restartKilledWrites: (b) SIG$1 $phase ($(committed) times committed)"
    for d in [0-9]*/.writeCommitted
    do
        find "${d%/.writeCommitted}" -type f -exec md5sum {} +
    done > "$work/committed.$2"
}
runUntil KILL '[ $(committed) -ge 8 ]' log.1 cellBlastFoam
stopped KILL 1
runUntil TERM '[ $(committed) -ge 16 ]' log.2 cellBlastFoam
stopped TERM 2
n=3
for stop in KILL:0 TERM:0 KILL:0.004 KILL:0.008
do
    c=$(committed)
    runUntilPoll=0 runUntil ${stop%:*} "writing $c && sleep ${stop#*:}" \
        log.$n cellBlastFoam
    stopped ${stop%:*} $n
    n=$((n + 1))
done
cellBlastFoam > log.$n 2>&1 || { tail -20 log.$n; exit 1; }
grep -q "^End" log.$n
for f in "$work"/committed.*
do
    md5sum -c --quiet "$f" \
        || { echo "restartKilledWrites: (b) a committed file changed ($f)"; exit 1; }
done
aside=$(cat log.* | grep -c "writeGuard: time directory" || true)
echo "restartKilledWrites: (b) $n starts, $aside times moved aside;" \
    "committed files unchanged"
[ "$aside" -ge 1 ] \
    || { echo "restartKilledWrites: (b) no kill landed inside a write"; exit 1; }
sameAsReference "$work/killed" 0

# (c)
cd "$work/cut"
cutAt=${times[-4]}
for t in "${times[@]}"
do
    if awk -v t="$t" -v c="$cutAt" 'BEGIN{exit !(t <= c)}'
    then
        cp -r "$ref/$t" .
    fi
done
mkdir -p solid
cp "$ref/solid/solid.h5" "$ref/solid/solid.xmf" solid/
mkdir -p postProcessing
cp -r "$ref/postProcessing/"* postProcessing/
mv "$cutAt/.writeCommitted" "$cutAt/.writeInProgress"
rm "$cutAt/uniform/fsiState"
cellBlastFoam > log.1 2>&1 || { tail -20 log.1; exit 1; }
grep "writeGuard: time directory .*$cutAt\" is incomplete" log.1 \
    || { echo "restartKilledWrites: (c) $cutAt was not moved aside"; exit 1; }
grep "Solid: removed" log.1 \
    || { echo "restartKilledWrites: (c) no step removed from solid.h5"; exit 1; }
sameAsReference "$work/cut" "$cutAt"
echo "restartKilledWrites: passed"
