#!/bin/bash
# x05: reused process ids in a blast case's stale lock: (a) the pid of a live 'sleep' with executable cellBlastFoam; (b) the pid of a cellBlastFoam running ANOTHER case; (c) the lock's pid is the new run's own pid (same executable, same case: a reset restarts pids from low numbers; made with exec): each start takes the stale lock over, or refuses clearly?
. "$(dirname "$0")/../lib.sh"
blast; A=$PWD; lk() { printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-01T10:00:00\ncase %s\n' $1 $(hostname) "$A" > $A/.runLock; }
sleep 60 & s=$!; lk $s; run 60 cellBlastFoam > log.a 2>&1; grep -a -i "stale\|in use" log.a | head -2 | cut -c1-250; fatal log.a 2; kill $s; rm -rf [1-9]* postProcessing solid .runLock
cp -r $ADV/blastBase/axisymmetricPreview $W/B; (cd $W/B && rm -rf postProcessing solid [1-9]* && blastEnd 2e-8 1e-9 && exec cellBlastFoam > log.B 2>&1) & b=$!; cd $A
waitFor 30 test -f $W/B/.runLock; bp=$(sed -n 's/^pid //p' $W/B/.runLock); echo "B runs as pid $bp"; lk $bp; run 60 cellBlastFoam > log.b 2>&1; grep -a -i "stale\|in use" log.b | head -2 | cut -c1-250; fatal log.b 2; kill $b 2>/dev/null; pkill -P $b 2>/dev/null; kill $bp 2>/dev/null; wait $b 2>/dev/null; rm -rf [1-9]* postProcessing solid .runLock
run 60 bash -c 'printf "pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-01T10:00:00\ncase %s\n" $$ $(hostname) "$PWD" > .runLock; exec cellBlastFoam' > log.c 2>&1; grep -a -i "stale\|in use" log.c | head -2 | cut -c1-250; fatal log.c 3; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; echo "lock after: $(lockOf)"
