#!/bin/bash
# f60 (class 3, a stale lock whose process id now belongs to a live run of the same executable in another case): case A (bd) restarted to 6e-9 in the background; case B (another bd copy) gets a .runLock as B's earlier run would have left it (B's case path) but with A's running process id. cellBlastFoam in B: takes the lock over as stale (that process runs in another case), or refuses naming the process and its case; a refusal that says B is in use without saying the process works elsewhere is UNCLEAR low.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/A; cd $W/A; blastEnd 6e-9 1e-9; latest; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 1; cat .runLock > $W/lockA
bd; rs; sed "s|$W/A|$W/blast|" $W/lockA > .runLock; echo "   B's lock: $(lk)"
tryt 120 "run in B with a lock naming B and A's live process" cellBlastFoam; cont; wait $p; echo "   A rc=$?"
