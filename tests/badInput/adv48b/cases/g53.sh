#!/bin/bash
# g53 (class 3, solidToFoam while the run writes solid.h5) bd restarted to 3e-9 in the background; once the lock is there, solidToFoam solid/solid.h5: refused naming the run (the case in use), nothing written; after the run, solidToFoam converts the solid's times 1e-09 2e-09 3e-09, each once.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -s .runLock; sleep 2; tryt 60 "solidToFoam during the run" solidToFoam solid/solid.h5; echo "   lock: $(lk | cut -c1-120)"; wait $p; echo "   run rc=$?"
tryt 120 "solidToFoam after the run" solidToFoam solid/solid.h5; echo "   solid times: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' ')"; after
