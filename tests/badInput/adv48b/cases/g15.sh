#!/bin/bash
# g15 (class 3, a lock of another host) a real lock of a run of this case (copied while a restart ran, the run then killed) with its host name changed to another host's: the next restart is refused naming the other host and the process (a lock of another host cannot be judged stale), never taken over; and the message says how to remove it.
. "$(dirname "$0")/../lib.sh"
bd; rs; cellBlastFoam > ../run1.log 2>&1 & p=$!; waitFor 60 test -s .runLock; cp .runLock ../lock0; kill -KILL $p; wait $p 2>/dev/null; echo "   lock was: $(tr '\n' ';' < ../lock0 | cut -c1-250)"
h=$(hostname); sed "s/$h/otherhost.example.org/g" ../lock0 > .runLock; grep -c otherhost .runLock | sed 's/^/   lines naming otherhost: /'; rm -rf 3e-09; sums > ../s0
tryt 120 "lock of otherhost" cellBlastFoam; echo "   lock now: $(lk | cut -c1-200)"; echo "   changed: $(changed ../s0)"
