#!/bin/bash
# d69 (class 3, d23 again with the two solidToFoam started at the same instant, 5 trials on the finished preview; d23 waited for the lock and the first had ended): in each trial one refused naming the other (the lock) or both ran one after the other; the converted region complete (its points file and each time's D field present) after each trial.
. "$(dirname "$0")/../lib.sh"
bd; for t in 1 2 3 4 5; do rm -rf constant/solid [0-9]*/solid; solidToFoam solid/solid.h5 > ../a 2>&1 & a=$!; solidToFoam solid/solid.h5 > ../b 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?
  echo "trial $t: rc $ra $rb | $(grep -a -m1 -i "lock\|running\|refus\|error" ../a | cut -c1-160) | $(grep -a -m1 -i "lock\|running\|refus\|error" ../b | cut -c1-160) | region: $(ls constant/solid/polyMesh 2>/dev/null | tr "\n" " ") $(ls 2e-09/solid 2>/dev/null | tr "\n" " ")"; done
