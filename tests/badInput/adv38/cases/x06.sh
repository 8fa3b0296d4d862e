#!/bin/bash
# x06: planeWave (Python, neuronFsi.caseLock) on a finished blast case whose stale lock names its own pid (exec: the pid reused by the same tool after a reset) and, second, the pid of a live 'sleep' with executable planeWave: taken over or refused clearly?
. "$(dirname "$0")/../lib.sh"
blastDone
run 120 bash -c 'printf "pid %s\nhost %s\nexecutable planeWave\nstarted 2026-12-01T10:00:00\ncase %s\n" $$ $(hostname) "$PWD" > .runLock; exec planeWave -Z 20e-6 -dz 50e-9' > log.c 2>&1; grep -a -i "stale\|in use" log.c | head -2 | cut -c1-250; fatal log.c 3; echo "lock after: $(lockOf)"; rm -f .runLock
sleep 60 & s=$!; printf "pid %s\nhost %s\nexecutable planeWave\nstarted 2026-12-01T10:00:00\ncase %s\n" $s $(hostname) "$PWD" > .runLock
run 120 planeWave -Z 20e-6 -dz 50e-9 > log.d 2>&1; grep -a -i "stale\|in use" log.d | head -2 | cut -c1-250; fatal log.d 2; kill $s; echo "lock after: $(lockOf)"
