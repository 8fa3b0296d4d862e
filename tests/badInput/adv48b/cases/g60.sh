#!/bin/bash
# g60 (class 3, a lock that is a hard link to a live run's lock) case A (bd) restarting to 3e-9 holds its .runLock; case B (another bd copy) gets .runLock as a hard link to A's; B's restart: refused (a lock naming another case) without writing through the link: A's lock unchanged (bytes and link count kept) and A's run finishes.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/A; cd $W/A; rs; blastEnd 1e-8 1e-9; cellBlastFoam > ../runA.log 2>&1 & p=$!; waitFor 60 test -s .runLock; md5sum .runLock > ../l0
bd; rs; blastEnd 1e-8 1e-9; ln $W/A/.runLock .runLock; tryt 120 "B with a hard link to A's live lock" cellBlastFoam; echo "   A's lock: $(md5sum -c ../l0 2>&1 | cut -c1-80), links $(stat -c %h $W/A/.runLock 2>/dev/null)"; after
wait $p; echo "   A's run rc=$? $(grep -a -m1 FATAL ../runA.log)"
