#!/bin/bash
# One run per case (issue 19, class 3; src/foamTools/caseLock.H), on the
# 1D pulse-layer FSI case in a scratch copy:
#  - while a run goes on, a second cellBlastFoam in the same case exits
#    non-zero, naming the running process and the lock file, and writes
#    nothing; the first run's results are those of a run alone (its
#    coupling log equal to the reference's, bitwise);
#  - a run killed with SIGKILL leaves its lock; the next run says it
#    removes a stale lock and runs;
#  - a lock of another host is refused with the file to remove named;
#  - a lock whose process id belongs to another executable (a reused id)
#    is stale;
#  - every run that ends (also in a fatal error) removes its lock;
#  - an empty lock and a directory in place of the lock are refused as
#    such; a lock naming another case says so; a run records its case;
#  - a run through a symbolic link to the case is a run of the same case;
#  - a solver started by an Allrun whose shell is killed alone (SIGTERM,
#    SIGKILL) keeps the case locked until its end.
# The runs over the first run's results start anew with -overwrite.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
. "$here/../lib/checks.sh"
work=$(mktemp -d)
pids=()
[ -n "${KEEP_WORK:-}" ] || trap 'for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done; rm -rf "$work"' EXIT

cp -r "$here/pulseLayer" "$work/ref"
(cd "$work/ref" && sed -i "s/^\(endTime *\)[0-9.e+-]*;/\12e-8;/" system/controlDict \
    && blockMesh > log.blockMesh 2>&1)
cp -r "$work/ref" "$work/case"
(cd "$work/ref" && cellBlastFoam > log.cellBlastFoam 2>&1)
check "a run alone removes its lock" "[ ! -e '$work/ref/.runLock' ]"

# 1. A second run while the first goes on (the first slowed down with
#    SIGSTOP so that it is surely running when the second starts)
cd "$work/case"
cellBlastFoam > log.first 2>&1 &
first=$!; pids+=("$first")
for _ in $(seq 100); do [ -s .runLock ] && break; sleep 0.1; done
kill -STOP "$first"
status=0; cellBlastFoam > log.second 2>&1 || status=$?
kill -CONT "$first"
check "the second run exits non-zero" "[ $status -ne 0 ]"
check "its message names the first run's process and the lock file" \
    "grep -q 'is in use by cellBlastFoam (process $first on host' log.second \
     && grep -q 'remove $work/case/.runLock' log.second"
wait "$first"
check "the first run ends normally and removes its lock" \
    "grep -q '^End' log.first && [ ! -e .runLock ]"
check "the first run's coupling log equals the reference's" \
    "cmp -s postProcessing/fsi/0/coupling.dat '$work/ref/postProcessing/fsi/0/coupling.dat'"

# 2. A killed run leaves a stale lock; the next run takes over. The runs
#    from here on start anew (startFrom startTime): the first run wrote
#    its last step, so a latestTime run would have nothing left to do and
#    end before it can be stopped or killed
foamDictionary -entry startFrom -set startTime system/controlDict > /dev/null
cellBlastFoam -overwrite > log.killed 2>&1 &
killed=$!; pids+=("$killed")
for _ in $(seq 100); do [ -s .runLock ] && break; sleep 0.1; done
kill -9 "$killed"; wait "$killed" 2>/dev/null || true
check "a killed run leaves its lock" "[ -s .runLock ]"
status=0; cellBlastFoam -overwrite > log.afterKill 2>&1 || status=$?
check "the next run removes the stale lock and runs" \
    "[ $status -eq 0 ] && grep -q 'Removing the stale run lock' log.afterKill \
     && [ ! -e .runLock ]"

# 3. A lock of another host
printf 'pid 1\nhost another-host\nexecutable cellBlastFoam\nstarted 2026-01-01T00:00:00\ncase %s\n' \
    "$PWD" > .runLock
status=0; cellBlastFoam > log.otherHost 2>&1 || status=$?
check "a lock of another host is refused, the file to remove named" \
    "[ $status -ne 0 ] && grep -q 'on host another-host' log.otherHost \
     && grep -q 'remove $work/case/.runLock' log.otherHost && [ -s .runLock ]"

# 4. A reused process id (a live process of another executable)
sleep 60 &
sleeper=$!; pids+=("$sleeper")
printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-01-01T00:00:00\ncase %s\n' \
    "$sleeper" "$(hostname)" "$PWD" > .runLock
status=0; cellBlastFoam -overwrite > log.reused 2>&1 || status=$?
check "a lock whose process runs another executable is stale" \
    "[ $status -eq 0 ] && grep -q 'Removing the stale run lock' log.reused"

# 4b. A lock written long before the process of its id started (left by a
# reset; the id now the new run's own: adv38 x05(c), refused as "in use by
# cellBlastFoam", itself): stale
status=0
bash -c 'printf "pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-01-01T00:00:00\ncase %s\n" $$ "$(hostname)" "$PWD" > .runLock; exec cellBlastFoam -overwrite' > log.ownPid 2>&1 || status=$?
check "a lock older than the process of its id (the run's own id) is stale" \
    "[ $status -eq 0 ] && grep -q 'Removing the stale run lock' log.ownPid && [ ! -e .runLock ]"

# 5. A run ending in a fatal error removes its lock
mv constant/fsiProperties constant/fsiProperties.moved
status=0; cellBlastFoam > log.fatal 2>&1 || status=$?
check "a run that ends in a fatal error removes its lock" \
    "[ $status -ne 0 ] && grep -q 'FOAM FATAL' log.fatal && [ ! -e .runLock ]"

# 6. Locks that are not ours to check (issue 19, adversarial pass: an
#    empty or directory .runLock was "in use by another run (process -1 on
#    host , ...)"; a lock copied with a case did not say so)
: > .runLock
status=0; cellBlastFoam > log.emptyLock 2>&1 || status=$?
check "an empty lock is refused as empty, the file named" \
    "[ $status -ne 0 ] && grep -q 'run lock $work/case/.runLock of the case $work/case is empty or damaged' log.emptyLock \
     && [ -e .runLock ] && [ ! -s .runLock ]"
rm .runLock; mkdir .runLock
status=0; cellBlastFoam > log.dirLock 2>&1 || status=$?
check "a directory in place of the lock is refused as a directory" \
    "[ $status -ne 0 ] && grep -q 'run lock $work/case/.runLock of the case $work/case is a directory' log.dirLock \
     && [ -d .runLock ]"
rmdir .runLock
printf 'pid 1\nhost another-host\nexecutable cellBlastFoam\nstarted 2026-01-01T00:00:00\ncase /somewhere/original\n' > .runLock
status=0; cellBlastFoam > log.copiedLock 2>&1 || status=$?
check "a lock of another case says so" \
    "[ $status -ne 0 ] && grep -q 'The lock names another case, /somewhere/original' log.copiedLock"
rm .runLock
mv constant/fsiProperties.moved constant/fsiProperties
cellBlastFoam -overwrite > log.lockCase 2>&1 &
own=$!; pids+=("$own")
for _ in $(seq 100); do [ -s .runLock ] && break; sleep 0.1; done
kill -STOP "$own"
check "a run records its case in the lock" "grep -qx 'case $work/case' .runLock"
kill -CONT "$own"
wait "$own" || true

# 7. The same case through a symbolic link (issue 19, adversarial pass
#    cc_twoSolidSymlink: refused as "The lock names another case"): the
#    lock records the real path, the second run is refused as a run of
#    this case
ln -s "$work/case" "$work/link"
cellBlastFoam -overwrite > log.linkFirst 2>&1 &
own=$!; pids+=("$own")
for _ in $(seq 100); do [ -s .runLock ] && break; sleep 0.1; done
kill -STOP "$own"
status=0; cellBlastFoam -case "$work/link" > "$work/log.link" 2>&1 || status=$?
kill -CONT "$own"
wait "$own" || true
check "a run through a link to the case is refused as the same case" \
    "[ $status -ne 0 ] && grep -q 'is in use by cellBlastFoam (process $own' '$work/log.link' \
     && ! grep -q 'another case' '$work/log.link'"

# 8. A solver started by an Allrun whose shell is then killed alone (adv36
#    v69, v38: its exit trap removed the lock, or with SIGKILL the lock
#    named a dead process; a solver started by hand ran beside the orphan
#    and force.dat held rows of both): the solver takes the Allrun's lock
#    over, so a second run is refused naming it, and the lock goes at the
#    orphan's end
rm -f "$work/link"
cat > "$work/case/AllrunSolver" <<'ALLRUN'
#!/bin/bash
cd "${0%/*}" || exit 1
. "$PROJECT_DIR"/etc/RunFunctions
allrunLock
cellBlastFoam -overwrite > log.allrunSolver 2>&1
ALLRUN
chmod +x AllrunSolver
for sig in TERM KILL
do
    PROJECT_DIR="$here/../.." setsid ./AllrunSolver &
    allrun=$!; pids+=("$allrun")
    solver=
    for _ in $(seq 200)
    do
        solver=$(pgrep -s "$allrun" cellBlastFoam || true)
        [ -n "$solver" ] && grep -qx "pid $solver" .runLock 2>/dev/null && break
        sleep 0.05
    done
    pids+=("$solver")
    kill -STOP "$solver"
    kill -"$sig" "$allrun"; wait "$allrun" 2>/dev/null || true
    status=0; cellBlastFoam -overwrite > "log.byHand$sig" 2>&1 || status=$?
    kill -CONT "$solver"
    check "an Allrun's shell killed (SIG$sig) while its solver runs: a solver by hand is refused naming the orphan" \
        "[ $status -ne 0 ] && grep -q 'is in use by cellBlastFoam (process $solver on host' log.byHand$sig"
    check "the Allrun's solver said it took the lock over" \
        "grep -q 'Running under the run lock .* taken over by this process' log.allrunSolver"
    for _ in $(seq 600); do [ -e /proc/$solver ] || break; sleep 0.1; done
    check "the orphan runs to its end and the lock goes with it (SIG$sig)" \
        "grep -q '^End' log.allrunSolver && [ ! -e .runLock ]"
done
rm AllrunSolver
exit $fail
