#!/bin/bash
# k51 (class 3, solidToFoam while the run writes solid.h5): bd restarted to 30e-9 in the background; while it runs, solidToFoam (all times) in the case, three times 1 s apart. Expected: refused naming the running run, or each conversion reads a consistent solid.h5 (no HDF5 error, no half-written step); the run undisturbed and its solid.h5 whole (h5steps = its commits).
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 30e-9 1e-9; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 1
for i in 1 2 3; do tryt 120 "solidToFoam #$i while the run goes" solidToFoam solid/solid.h5; sleep 1; done; echo "   run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
wait $p; echo "   run rc=$? | $(grep -a -m1 'FATAL' log.bg | cut -c1-150)"; after; echo "   xmf steps $(xmfsteps solid/solid.xmf)"
