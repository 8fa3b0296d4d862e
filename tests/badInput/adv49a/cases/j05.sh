#!/bin/bash
# CASETIMEOUT=900
# j05 (class 3, fix19e's huge lock (adv48b g14) varied: what stands at .runLock): bd, restart to 2.06e-9 (one step of the restart time's deltaT 5.6e-11 s; writeInterval
# 1e-11; a run that takes the lock over is short): cellBlastFoam and solidToFoam solid/solid.h5 with .runLock (a) a sparse
# file of 65537 bytes (one above the limit), (b) 65536 zero bytes (at the limit: read), (c) empty, (d) 300 random bytes,
# (e) a directory, (f) a symbolic link to /dev/zero, (g) a FIFO, (h) a lock of this host's format naming pid 4194305 (above
# pid_max), (i) a lock naming a live `sleep` started here, as its executable 'sleep' (a live process of another program:
# refused, it cannot be judged over), (j) a lock naming that live sleep as executable cellBlastFoam (a reused pid: taken
# over, said), (k) another host's lock; then (l) cellIndentationFoam (smoke ind) and cellMesh (a preview copy) under a
# sparse 8 GiB lock, planeWave -case . -check under (b), (c), (f), (g). Refused (rc 1, within seconds, naming .runLock and
# what it is, nothing changed, the lock left as it was) or taken over only where the lock is provably stale ((j)); never
# a hang (60 s), never read whole.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 2.06e-9 1e-11; rm -f .runLock; sums > ../s0; H=$(hostname)
lock() { printf 'pid %s\nhost %s\nexecutable %s\nstarted %s\ncase %s\n' "$1" "$2" "$3" "$(date +%Y-%m-%dT%H:%M:%S)" "$(pwd -P)" > .runLock; }
both() { local l=$1; tryt 60 "$l: cellBlastFoam" cellBlastFoam; echo "   sig: $(sig) | msg: $(msg 3 | cut -c1-330)"; echo "   changed: $(changed ../s0 | tr '\n' ' ') | lock now: $(ls -ld .runLock 2>/dev/null | cut -c1-11) $(stat -c %s .runLock 2>/dev/null) B"
  tryt 60 "$l: solidToFoam" solidToFoam solid/solid.h5; echo "   sig: $(sig) | msg: $(msg 3 | cut -c1-330)"; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"; }
clean() { rm -rf .runLock 2.01e-09; cd $W; rm -rf blast; bd; latest; blastEnd 2.06e-9 1e-11; rm -f .runLock; }
truncate -s 65537 .runLock; both "(a) 65537 B sparse"; clean
head -c 65536 /dev/zero > .runLock; both "(b) 65536 zero bytes"; clean
: > .runLock; both "(c) empty"; clean
head -c 300 /dev/urandom > .runLock; both "(d) 300 random bytes"; clean
mkdir .runLock; both "(e) a directory"; clean
ln -s /dev/zero .runLock; both "(f) link to /dev/zero"; clean
mkfifo .runLock; both "(g) a FIFO"; clean
lock 4194305 $H cellBlastFoam; both "(h) pid 4194305"; clean
sleep 600 & S=$!; lock $S $H sleep; both "(i) live sleep $S, executable sleep"; clean
lock $S $H cellBlastFoam; both "(j) live sleep $S, executable cellBlastFoam"; kill $S; clean
lock 12345 another-host.example cellBlastFoam; both "(k) another host"; clean
cd $W; ind; truncate -s 8G .runLock; tryt 60 "(l) cellIndentationFoam, 8 GiB lock" /usr/bin/time -f "maxRSS %M kB" cellIndentationFoam; grep -a maxRSS $W/try.log; echo "   results: $(ls postProcessing 2>/dev/null)"
cd $W; rm -rf blast; blast; truncate -s 8G .runLock; cp constant/cell.msh ../cell0; tryt 60 "(l) cellMesh, 8 GiB lock" /usr/bin/time -f "maxRSS %M kB" cellMesh; grep -a maxRSS $W/try.log; cmp -s constant/cell.msh ../cell0 && echo "   cell.msh unchanged" || echo "   cell.msh CHANGED"
cd $W; rm -rf blast; bd; for k in b c f g; do rm -rf .runLock; case $k in b) head -c 65536 /dev/zero > .runLock;; c) : > .runLock;; f) ln -s /dev/zero .runLock;; g) mkfifo .runLock;; esac
  tryt 60 "(m $k) planeWave -case . -check" planeWave -case . -check; echo "   msg: $(grep -a -m1 'error' $W/try.log | cut -c1-300)"; done
