#!/bin/bash
# i14 (class 1, solidSubcycles changed between a kill and its restart): mbd's prepared case (subcycles 4) started from 0 to
# 6e-9, SIGKILLed after its 2nd commit (killAfter), then (a) restarted with the .allrun's solidSubcycles set to 1: refused naming
# constant/fsiProperties(.allrun) and solidSubcycles, nothing changed; (b) set to 4 again: continues to 6e-9, and its logs,
# solid.h5 and 6e-09/p equal a straight run's (exact kill-and-restart with subcycles: i13's straight run made here too).
. "$(dirname "$0")/../lib.sh"
mbd; fresh; e6; tryt 500 "straight 0 -> 6e-9" cellBlastFoam; away straight
mbd; fresh; e6; cellBlastFoam > log.killed 2>&1 & p=$!; killAfter 2 $p; rm -f .runLock; latest; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"
sed -i 's/solidSubcycles *4/solidSubcycles 1/' constant/fsiProperties.allrun; echo "   .allrun: $(tr '\n' ' ' < constant/fsiProperties.allrun)"; sums > ../s0
tryt 300 "(a) restart with solidSubcycles 1" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
sed -i 's/solidSubcycles *1/solidSubcycles 4/' constant/fsiProperties.allrun; tryt 500 "(b) restart with 4 again" cellBlastFoam; cont; after; cmp6 $W/straight
