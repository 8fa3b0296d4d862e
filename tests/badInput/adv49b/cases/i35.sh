#!/bin/bash
# i35 (class 1/6, maxSteps at a restart of the indentation): ik (the smoke indentation with 10x finer steps, killed 1 s
# after its first checkpoint, startFrom latestTime): the estimate is printed by a first restart with maxSteps 1 (refused);
# then maxSteps between the steps remaining and the whole table's (if they differ) and maxSteps below the remaining:
# each accepted or refused consistently with what the message says it counts (the remaining rows or the whole table), and
# a refused restart changes nothing (force.dat, peaks.dat, restart.h5, solid.h5 kept).
. "$(dirname "$0")/../lib.sh"
ik; ms() { sed -i '/^maxSteps/d' system/controlDict; echo "maxSteps $1;" >> system/controlDict; }; sums > ../s0; forceOk postProcessing/indentation/force.dat
ms 1; tryt 120 "restart, maxSteps 1" cellIndentationFoam; grep -a -i -m3 'step' $W/try.log | cut -c1-250 | sed 's/^/   /'; echo "   changed: $(changed ../s0)"
N=$(grep -a -o 'about [0-9]*\|[0-9][0-9]* steps\|[0-9][0-9]* time steps' $W/try.log | grep -o '[0-9]*' | head -1); echo "   N = $N"
[ -n "$N" ] && for m in $((N/2)) $((N-1)) $N; do cp -a $W/ind $W/k; cd $W/k; ms $m; tryt 400 "restart, maxSteps $m" cellIndentationFoam; forceOk postProcessing/indentation/force.dat; cd $W; rm -rf $W/k; cd $W/ind; done
