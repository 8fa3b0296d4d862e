#!/bin/bash
# g15 (class 3, stale locks): a killed blast run's .runLock edited: (a) its host changed to another name; (b) its pid replaced by this script's own bash's (alive, another executable); (c) the lock cut in the middle of a line (a partial write); (d) its pid replaced by a zombie's. Restart each: (a) refused and never taken over, with what to do; (b), (d) taken over as stale; (c) refused as damaged, with what to do?
. "$(dirname "$0")/../lib.sh"
blast; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f 1e-09/.writeCommitted; kill -KILL $p; wait $p 2>/dev/null; latest; echo "   stale lock: $(lockOf)"; cd ..
for c in a b c d; do cp -r blast $c; done
cd a; sed -i "s/^host .*/host otherhost-g15/" .runLock; echo "   (a) $(lockOf)"; tryf "(a) another host's lock" cellBlastFoam; [ -f .runLock ] && echo "   lock still there: $(lockOf | cut -c1-80)"
cd ../b; sed -i "s/^pid .*/pid $$/" .runLock; echo "   (b) $(lockOf)"; tryf "(b) pid of a live bash" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
cd ../c; n=$(stat -c %s .runLock); head -c $((n/2)) .runLock > .rl && mv .rl .runLock; echo "   (c) $(lockOf)"; tryf "(c) a lock cut in half" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
cd ../d; bash -c 'sleep 0.2 & exec sleep 30' & zp=$!; sleep 0.6; z=$(pgrep -P $zp sleep); echo "   zombie $z state $(awk '{print $3}' /proc/$z/stat 2>/dev/null)"; sed -i "s/^pid .*/pid $z/" .runLock; tryf "(d) pid of a zombie" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kill $zp 2>/dev/null
