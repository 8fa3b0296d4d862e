#!/bin/bash
# f10 (class 3, adv46b d28 with a restart long enough to be beside: the finished preview restarted to 8e-9 (about 420
# steps), solidToFoam 1 s after the solver's lock appears): solidToFoam refused naming the running solver; the solver
# finishes and its solid.h5/solid.xmf agree.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 8e-9 1e-9; cellBlastFoam > ../l1 2>&1 & p=$!; waitFor 30 grep -q cellBlastFoam .runLock; sleep 1; echo "solver running: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
tryt 100 "solidToFoam beside the solver" solidToFoam solid/solid.h5; wait $p; echo "   solver rc=$?; h5 $(h5steps solid/solid.h5) steps, xmf $(xmfsteps solid/solid.xmf); times $(ls -d [0-9]* | tr '\n' ' ')"
