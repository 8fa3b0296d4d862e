#!/bin/bash
# CASETIMEOUT=300
# u16 (fix19i/lead's caseLock correction "the lock's process identity for this host's locks only; a lock of another host
# is judged by its case path", varied: the machine's host name changed since the lock was written - a container
# re-created, a laptop on another network - so a stale lock of this machine names another host): bd restarted to 3e-9 with
# a .runLock naming (a) host "oldname" (this machine's former name), a dead pid, this case's path; (b) the same with
# the pid of a live process of this host (pid 1); (c) planeWave and solidToFoam on (a)'s case. Expected: refused naming
# the host and how to go on (remove the lock if that run is over), or taken over as stale with a note; no run started
# beside a live run. A refusal that does not say what to do = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; sleep 100 & p=$!; kill -KILL $p; wait $p 2>/dev/null
lk() { printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-06T10:00:00\ncase %s\n' "$1" "$2" "$PWD" > .runLock; }
lk $p oldname; tryt 120 "(a) a lock of host 'oldname' (dead pid $p, this case)" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 4 | cut -c1-400)"
lk $p oldname; tryt 120 "(c1) planeWave on it" planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"
lk $p oldname; tryt 120 "(c2) solidToFoam on it" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-250)"
lk 1 oldname; tryt 120 "(b) a lock of host 'oldname' with pid 1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 4 | cut -c1-400)"
