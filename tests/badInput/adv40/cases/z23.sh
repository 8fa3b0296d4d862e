#!/bin/bash
# z23: purgeWrite 1 (OpenFOAM deletes the older time at each write): blast to 4 ns writing every 1 ns, SIGKILLed after its 2nd commit, restarted from latestTime: continues, and the final probes/solid.h5 equal an uninterrupted purgeWrite-1 run (sameSeries)? and solid.h5's steps
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 4e-9 1e-9; sed -i 's/^purgeWrite .*/purgeWrite 1;/' system/controlDict; cp -r $W/blast $W/ref
(cd $W/ref && cellBlastFoam > log.ref 2>&1; echo "reference rc=$? times $(ls -d [1-9]*)")
cellBlastFoam > log.k 2>&1 & p=$!; killAfter 2 $p; echo "after kill: $(ls -da [1-9]* .[1-9]* 2>/dev/null | tr '\n' ' ')"; latest
try "restart" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5) (reference $(h5steps $W/ref/solid/solid.h5))"; sameSeries $W/ref
