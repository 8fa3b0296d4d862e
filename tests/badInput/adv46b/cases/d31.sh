#!/bin/bash
# d31 (class 3, a parallel run (mpirun -np 2, decomposed) and a serial run of the same blast case at once, both orders): the second refused naming the first; the first unharmed.
. "$(dirname "$0")/../lib.sh"
pblast; cp -a $W/blast $W/blast2
mpirun --allow-run-as-root --oversubscribe -np 2 cellBlastFoam -parallel > ../l1 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 2; tryt 60 "(a) serial beside the parallel run" cellBlastFoam; kill $p; wait $p; echo "   parallel rc=$?"
cd $W/blast2; cellBlastFoam > ../l2 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 2; tryt 60 "(b) parallel beside the serial run" mpirun --allow-run-as-root --oversubscribe -np 2 cellBlastFoam -parallel; kill $p; wait $p; echo "   serial rc=$?"
