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
#  (b2) the same time with its .writeCommitted empty (a power loss after
#      the rename) and 64 bytes of its p zeroed: moved aside too, naming
#      the empty marker, the same final fields;
#  (c) SIGKILL at random instants (2-12 % of the uninterrupted run's time
#      after each start), restarted
#      from latestTime until it completes: at least one kill must have
#      landed inside a write (a time moved aside), and the final p, U, rho,
#      rhoU, rhoE must equal those of (a) bitwise;
#  (d) on 2 MPI ranks: a decomposed run, and a copy cut back to its 3rd
#      write where only processor1's copy of that time is interrupted
#      (truncated p, in-progress marker): both ranks must move the time
#      aside (else they would start from different times) and reach the
#      decomposed run's final fields bitwise.
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
setup() {
    mkdir "$work/$1"
    cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} "$work/$1"/
    rm -rf "$work/$1/constant/polyMesh"
    sed -i 's/^writePrecision .*/writePrecision  17;/; s/^timePrecision .*/timePrecision   17;/; s/^writeControl .*/writeControl    timeStep;/; s/^writeInterval .*/writeInterval   1;/; s/^endTime .*/endTime         4e-8;/' "$work/$1/system/controlDict"
    ( cd "$work/$1" && cp -r 0.orig 0 && blockMesh > log.blockMesh )
}
same() {    # same RUN: final fields of RUN equal to those of a
    sameFiles "$work/a/$last" "$work/$1/$last" p U rho rhoU rhoE
}

setup a
t0=$(date +%s%N)
( cd "$work/a" && rhoRiemannFoam > log.1 )
runMs=$(( ($(date +%s%N) - t0)/1000000 ))
times=($(foamListTimes -case "$work/a"))
last=${times[-1]}
for t in "${times[@]}"
do
    [ -f "$work/a/$t/.writeCommitted" ] || { echo "restartKilledWrites: $t has no commit marker"; exit 1; }
done
echo "restartKilledWrites: uninterrupted run: ${#times[@]} writes, last $last s, $runMs ms"

# (b) controlled: truncated third write with the in-progress marker
setup b
cut=${times[2]}
for t in "${times[@]:0:3}"; do cp -r "$work/a/$t" "$work/b/"; done
# the logs the restart continues (their bytes up to each commit are
# recorded in its marker and checked at a restart)
cp -r "$work/a/postProcessing" "$work/b/"
head -c 2000 "$work/a/$cut/p" > "$work/b/$cut/p"
mv "$work/b/$cut/.writeCommitted" "$work/b/$cut/.writeInProgress"
( cd "$work/b" && rhoRiemannFoam > log.1 )
grep -q "writeGuard: time directory .*$cut\" is incomplete" "$work/b/log.1" \
    || { echo "restartKilledWrites: (b) the truncated time $cut was not moved aside"; exit 1; }
[ -d "$work/b/$cut.incomplete" ] || { echo "restartKilledWrites: (b) no $cut.incomplete"; exit 1; }
same b || exit 1
echo "restartKilledWrites: (b) truncated write of $cut s moved aside, final fields bitwise equal"

# (b2) what a power loss after the commit's rename can leave: the third
# write's .writeCommitted empty (no digest, no file lines) and 64 bytes of
# its p zeroed: an unfinished write, moved aside naming the empty marker
# (adv38 x33: taken as a commit, the run continued from the damaged p)
setup b2
for t in "${times[@]:0:3}"; do cp -r "$work/a/$t" "$work/b2/"; done
cp -r "$work/a/postProcessing" "$work/b2/"
: > "$work/b2/$cut/.writeCommitted"
/usr/bin/python3 - "$work/b2/$cut/p" <<'PY'
import sys
s = bytearray(open(sys.argv[1], "rb").read())
k = s.find(b"(", s.find(b"internalField")) + 200
s[k:k + 64] = b"\0"*64
open(sys.argv[1], "wb").write(s)
PY
( cd "$work/b2" && rhoRiemannFoam > log.1 )
grep -q "writeGuard: time directory .*$cut\" is incomplete (its .writeCommitted marker is empty" "$work/b2/log.1" \
    || { echo "restartKilledWrites: (b2) the time $cut with an empty marker was not moved aside naming it"; exit 1; }
[ -d "$work/b2/$cut.incomplete" ] || { echo "restartKilledWrites: (b2) no $cut.incomplete"; exit 1; }
same b2 || exit 1
echo "restartKilledWrites: (b2) $cut s with an empty commit marker moved aside, final fields bitwise equal"

# (b3) the same with the marker cut short instead of emptied: its first
# three lines kept (time, digest line, one file line), no closing "end"
# line (adv39 y12, y16: taken as a commit, only the files it still listed
# were checked, the run continued from the damaged p)
setup b3
for t in "${times[@]:0:3}"; do cp -r "$work/a/$t" "$work/b3/"; done
cp -r "$work/a/postProcessing" "$work/b3/"
grep -q '^end$' "$work/a/$cut/.writeCommitted" \
    || { echo "restartKilledWrites: (b3) the commit marker of $cut has no closing end line"; exit 1; }
head -n 3 "$work/a/$cut/.writeCommitted" > "$work/b3/$cut/.writeCommitted"
cp "$work/b2/$cut.incomplete/p" "$work/b3/$cut/p"
( cd "$work/b3" && rhoRiemannFoam > log.1 )
grep -q "writeGuard: time directory .*$cut\" is incomplete (its .writeCommitted marker is empty or cut short" "$work/b3/log.1" \
    || { echo "restartKilledWrites: (b3) the time $cut with a marker cut short was not moved aside naming it"; exit 1; }
[ -d "$work/b3/$cut.incomplete" ] || { echo "restartKilledWrites: (b3) no $cut.incomplete"; exit 1; }
same b3 || exit 1
echo "restartKilledWrites: (b3) $cut s with a commit marker cut short moved aside, final fields bitwise equal"

# (c) random SIGKILLs
setup c
kills=0
opt=""
for attempt in $(seq 1 100)
do
    ( cd "$work/c" && exec rhoRiemannFoam $opt > "log.$attempt" 2>&1 ) &
    pid=$!
    # a random instant in the first 2-12 % of an uninterrupted run (the
    # machine's load sets the scale), after a 0.2 s start-up
    sleep "$(awk -v r=$RANDOM -v T=$runMs 'BEGIN{printf "%.3f", 0.2 + (0.02 + 0.10*r/32768)*T/1000}')"
    if kill -KILL $pid 2>/dev/null
    then
        kills=$((kills + 1))
    fi
    wait $pid 2>/dev/null || true
    grep -q "^End" "$work/c/log.$attempt" && break
    # killed before its first time was committed: the latest time is the
    # start, and the probes' output of the killed run is there; a restart
    # is refused as a new start over results (resultGuard), so start anew
    opt=""
    grep -q "nothing to continue from" "$work/c/log.$attempt" && opt=-overwrite
done
grep -q "^End" "$work/c/log.$attempt" \
    || { echo "restartKilledWrites: (c) not finished after $attempt starts"; exit 1; }
hit=$(cat "$work/c"/log.* | grep -c "writeGuard: time directory" || true)
echo "restartKilledWrites: (c) $kills SIGKILLs, $hit inside a write (time moved aside), $attempt starts"
[ "$hit" -ge 1 ] || { echo "restartKilledWrites: (c) no kill landed inside a write; nothing tested"; exit 1; }
same c || exit 1
# (d) parallel: the incomplete time is discarded on every rank
decomposed() {
    setup "$1"
    cat > "$work/$1/system/decomposeParDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method          simple;
coeffs          { n (2 1 1); }
DICT
    sed -i 's/^endTime .*/endTime         1e-8;/' "$work/$1/system/controlDict"
    ( cd "$work/$1" && decomposePar > log.decompose 2>&1 )
}
decomposed pa
( cd "$work/pa" && mpirun -np 2 rhoRiemannFoam -parallel > log.1 2>&1 )
ptimes=($(foamListTimes -case "$work/pa/processor0"))
plast=${ptimes[-1]}
decomposed pd
pcut=${ptimes[2]}
for proc in 0 1
do
    for t in "${ptimes[@]:0:3}"; do cp -r "$work/pa/processor$proc/$t" "$work/pd/processor$proc/"; done
done
[ ! -d "$work/pa/postProcessing" ] || cp -r "$work/pa/postProcessing" "$work/pd/"
head -c 1500 "$work/pa/processor1/$pcut/p" > "$work/pd/processor1/$pcut/p"
mv "$work/pd/processor1/$pcut/.writeCommitted" "$work/pd/processor1/$pcut/.writeInProgress"
( cd "$work/pd" && mpirun -np 2 rhoRiemannFoam -parallel > log.1 2>&1 ) \
    || { echo "restartKilledWrites: (d) the parallel restart failed"; tail -20 "$work/pd/log.1"; exit 1; }
for proc in 0 1
do
    [ -d "$work/pd/processor$proc/$pcut.incomplete" ] \
        || { echo "restartKilledWrites: (d) processor$proc/$pcut not moved aside"; exit 1; }
    sameFiles "$work/pa/processor$proc/$plast" "$work/pd/processor$proc/$plast" \
        p U rho rhoU rhoE || { echo "restartKilledWrites: (d) processor$proc differs"; exit 1; }
done
echo "restartKilledWrites: (d) 2 ranks, $pcut s incomplete on processor1 only: moved aside on both, final fields bitwise equal"

echo "restartKilledWrites: passed (final p, U, rho, rhoU, rhoE bitwise equal to the uninterrupted run)"
