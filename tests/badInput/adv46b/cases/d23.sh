#!/bin/bash
# d23 (class 3, two solidToFoam at once on the finished preview): the second refused naming the first (the lock), the first converts completely; never two writers.
. "$(dirname "$0")/../lib.sh"
bd; solidToFoam solid/solid.h5 > ../l1 2>&1 & p=$!; waitFor 20 test -f .runLock; sleep 0.2; tryt 100 "second solidToFoam" solidToFoam solid/solid.h5; wait $p; echo "   first: rc=$? $(tail -1 ../l1 | cut -c1-100)"; ls constant/solid 1e-09 2>&1 | tr "\n" " "
