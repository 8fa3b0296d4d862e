#!/bin/bash
# d73 (class 3, d31 (b) again with a serial run long enough to be running (endTime 10 ns): a decomposed case run serially, then mpirun -np 2 -parallel started beside it): the parallel run refused naming the serial run (the lock), printed once; the serial run unharmed.
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 10e-9 1e-9; cellBlastFoam > ../l2 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 1; echo "   serial running: $(kill -0 $p 2>/dev/null && echo yes)"
tryt 60 "parallel beside the serial run" mpirun --allow-run-as-root --oversubscribe -np 2 cellBlastFoam -parallel; echo "   refusals printed: $(grep -a -c "in use by" $W/try.log)"; echo "   serial still running: $(kill -0 $p 2>/dev/null && echo yes || echo no)"; kill $p; wait $p; ls processor0 | tr "\n" " "
