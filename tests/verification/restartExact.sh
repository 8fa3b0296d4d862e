#!/bin/bash
# Restart of rhoRiemannFoam is exact: the pressure-pulse/rigid-wall case
# (tutorials/verification/waterPulseWall; writePrecision and timePrecision
# 17: the restart time is taken from the directory name; a write every
# 200 steps so that no write time shortens a step) run
#  (a) uninterrupted to 80 ns,
#  (b) stopped with SIGTERM after its second write and continued,
#  (c) killed with SIGKILL after its second write and continued,
# must give bitwise the same p, U, rho, rhoU, rhoE at the last common write:
# the conservative state is written with every time and read back.
# (With writeControl adjustableRunTime OpenFOAM shortens the step before a
# write time by an amount that depends on the start time of the run, so a
# continued run differs in the last bits of deltaT.)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for run in a b c
do
    mkdir "$work/$run"
    cp -r "$root/tutorials/verification/waterPulseWall"/{0.orig,system,constant} "$work/$run"/
    rm -rf "$work/$run/constant/polyMesh"
    sed -i 's/^writePrecision .*/writePrecision  17;/; s/^timePrecision .*/timePrecision   17;/; s/^writeControl .*/writeControl    timeStep;/; s/^writeInterval .*/writeInterval   200;/' "$work/$run/system/controlDict"
    ( cd "$work/$run" && cp -r 0.orig 0 && blockMesh > log.blockMesh )
done
( cd "$work/a" && rhoRiemannFoam > log.1 )
times=($(foamListTimes -case "$work/a"))
[ "${#times[@]}" -ge 3 ] || { echo "restartExact: too few writes"; exit 1; }
second=${times[1]}
last=${times[-1]}

for run in b c
do
    signal=TERM; [ $run = c ] && signal=KILL
    ( cd "$work/$run" && exec rhoRiemannFoam > log.1 ) &
    pid=$!
    # wait until the second write is complete: a time step logged after it
    for i in $(seq 1 1200)
    do
        if [ -n "$(awk -v t="Time = $second s" '$0==t{f=1;next} f&&/^Time = /{print; exit}' "$work/$run/log.1")" ]
        then
            break
        fi
        sleep 0.05
    done
    kill -$signal $pid 2>/dev/null || true
    wait $pid 2>/dev/null || true
    if [ -d "$work/$run/$last" ]; then
        echo "restartExact: run $run finished before SIG$signal; nothing tested"; exit 1
    fi
    from=$(foamListTimes -case "$work/$run" -latestTime | tail -1)
    echo "restartExact: run $run stopped by SIG$signal, continuing from $from s"
    ( cd "$work/$run" && rhoRiemannFoam > log.2 )
    grep -q "Restarting from the conservative state" "$work/$run/log.2"
done

status=0
for run in b c
do
    for f in p U rho rhoU rhoE
    do
        if ! cmp -s "$work/a/$last/$f" "$work/$run/$last/$f"
        then
            echo "restartExact: $f at $last s of run $run differs from the uninterrupted run"
            status=1
        fi
    done
done
[ $status -eq 0 ] && echo "restartExact: SIGTERM and SIGKILL restarts equal the uninterrupted run bitwise (p, U, rho, rhoU, rhoE at $last s): passed"
exit $status
