#!/bin/bash
# z23: purgeWrite 1 (OpenFOAM deletes the older time at each write): blast to 4 ns writing every 1 ns, SIGKILLed once 2e-09 is committed (the 1e-09 time purged), restarted from latestTime: continues, and the final probes/solid.h5 equal an uninterrupted purgeWrite-1 run (sameSeries)? and solid.h5's steps
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 4e-9 1e-9; sed -i 's/^purgeWrite .*/purgeWrite 1;/' system/controlDict; cp -r $W/blast $W/ref
(cd $W/ref && cellBlastFoam > log.ref 2>&1; echo "reference rc=$? times $(ls -d [1-9]*)")
cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f 2e-09/.writeCommitted; sleep 0.$((RANDOM % 3)); kill -KILL $p; wait $p 2>/dev/null; echo "killed once 2e-09 was committed"; echo "after kill: $(ls -da [1-9]* .[1-9]* 2>/dev/null | tr '\n' ' ')"; latest
try "restart" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5) (reference $(h5steps $W/ref/solid/solid.h5))"; sameSeries $W/ref
