#!/bin/bash
# Kills during writes lose nothing (src/foamTools/writeGuard.H): the
# pressure-pulse/rigid-wall case with a write every time step (so that
# most of the run is spent writing), writePrecision 17,
#  (a) run uninterrupted to the end;
#  (b) a write interrupted in a controlled way: a copy of (a) cut back to
#      its 3rd written time, whose p is truncated half way and which carries
#      the in-progress marker again (what a SIGKILL inside the write
#      leaves), continued from latestTime: the truncated time must be moved
#      aside and the run must reach bitwise the same final fields as (a);
#  (c) SIGKILL at random instants (0.1-0.6 s after each start), restarted
#      from latestTime until it completes: at least one kill must have
#      landed inside a write (a time moved aside), and the final p, U, rho,
#      rhoU, rhoE must equal those of (a) bitwise.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
setup() {
    mkdir "$work/$1"
    cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} "$work/$1"/
    rm -rf "$work/$1/constant/polyMesh"
    sed -i 's/^writePrecision .*/writePrecision  17;/; s/^timePrecision .*/timePrecision   17;/; s/^writeControl .*/writeControl    timeStep;/; s/^writeInterval .*/writeInterval   1;/; s/^endTime .*/endTime         4e-8;/' "$work/$1/system/controlDict"
    ( cd "$work/$1" && cp -r 0.orig 0 && blockMesh > log.blockMesh )
}
same() {    # same RUN: final fields of RUN equal to those of a
    local s=0
    for f in p U rho rhoU rhoE
    do
        if ! cmp -s "$work/a/$last/$f" "$work/$1/$last/$f"
        then
            echo "restartKilledWrites: $f at $last s of run $1 differs from the uninterrupted run"
            s=1
        fi
    done
    return $s
}

setup a
( cd "$work/a" && rhoRiemannFoam > log.1 )
times=($(foamListTimes -case "$work/a"))
last=${times[-1]}
for t in "${times[@]}"
do
    [ -f "$work/a/$t/.writeCommitted" ] || { echo "restartKilledWrites: $t has no commit marker"; exit 1; }
done
echo "restartKilledWrites: uninterrupted run: ${#times[@]} writes, last $last s"

# (b) controlled: truncated third write with the in-progress marker
setup b
cut=${times[2]}
for t in "${times[@]:0:3}"; do cp -r "$work/a/$t" "$work/b/"; done
head -c 2000 "$work/a/$cut/p" > "$work/b/$cut/p"
mv "$work/b/$cut/.writeCommitted" "$work/b/$cut/.writeInProgress"
( cd "$work/b" && rhoRiemannFoam > log.1 )
grep -q "writeGuard: time directory .*$cut\" is incomplete" "$work/b/log.1" \
    || { echo "restartKilledWrites: (b) the truncated time $cut was not moved aside"; exit 1; }
[ -d "$work/b/$cut.incomplete" ] || { echo "restartKilledWrites: (b) no $cut.incomplete"; exit 1; }
same b || exit 1
echo "restartKilledWrites: (b) truncated write of $cut s moved aside, final fields bitwise equal"

# (c) random SIGKILLs
setup c
kills=0
for attempt in $(seq 1 60)
do
    ( cd "$work/c" && exec rhoRiemannFoam > "log.$attempt" 2>&1 ) &
    pid=$!
    sleep "0.$((RANDOM % 6 + 1))"
    if kill -KILL $pid 2>/dev/null
    then
        kills=$((kills + 1))
    fi
    wait $pid 2>/dev/null || true
    grep -q "^End" "$work/c/log.$attempt" && break
done
grep -q "^End" "$work/c/log.$attempt" \
    || { echo "restartKilledWrites: (c) not finished after $attempt starts"; exit 1; }
hit=$(cat "$work/c"/log.* | grep -c "writeGuard: time directory" || true)
echo "restartKilledWrites: (c) $kills SIGKILLs, $hit inside a write (time moved aside), $attempt starts"
[ "$hit" -ge 1 ] || { echo "restartKilledWrites: (c) no kill landed inside a write; nothing tested"; exit 1; }
same c || exit 1
echo "restartKilledWrites: passed (final p, U, rho, rhoU, rhoE bitwise equal to the uninterrupted run)"
