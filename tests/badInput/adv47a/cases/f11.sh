#!/bin/bash
# f11 (class 2, adv46b d58 with an -overwrite run long enough to be killed in it: the finished preview (1e-09, 2e-09),
# cellBlastFoam -overwrite with endTime 2e-8 SIGKILLed 3 s and 8 s after its start, then a restart with startFrom
# latestTime (endTime 2e-8)): the earlier times and solid.h5 kept (as .<time>.overwritten or in place) and named by the
# restart's refusal; nothing of the earlier run lost.
. "$(dirname "$0")/../lib.sh"
for s in 3 8; do cd $W; rm -rf blast; bd; contents > ../c0; blastEnd 2e-8 1e-9; killAt $s cellBlastFoam -overwrite; echo "   after the kill: $(ls -a | tr "\n" " ")"; echo "   earlier contents lost: $(lost ../c0 | wc -l) of $(wc -l < ../c0)"
  latest; tryt 100 "   then a restart" cellBlastFoam; echo "   earlier contents lost now: $(lost ../c0 | wc -l); times $(ls -d [0-9]* .*overwritten* 2>/dev/null | tr '\n' ' ')"; done
