#!/bin/bash
# d28 (class 3, solidToFoam on a blast case while cellBlastFoam restarts in it): solidToFoam refused naming the running solver; the solver then finishes and its solid.h5/solid.xmf agree.
. "$(dirname "$0")/../lib.sh"
bd; rs; cellBlastFoam > ../l1 2>&1 & p=$!; waitFor 30 grep -q cellBlastFoam .runLock; sleep 1; tryt 100 "solidToFoam beside the solver" solidToFoam solid/solid.h5; wait $p; echo "   solver rc=$?; h5 $(h5steps solid/solid.h5) steps, xmf $(xmfsteps solid/solid.xmf)"; ls constant
