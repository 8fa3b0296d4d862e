#!/bin/bash
# g21 (class 3, the preview's Allrun twice at once in one case) two ./Allrun $PREV -endTime 2e-9 -noRun started 0.5 s apart in one fresh copy: one refused at once naming the other (the case in use), the other prepares the case; afterwards a third identical Allrun -noRun finds the case prepared (nothing redone, exit 0) and cellBlastFoam starts on it (endTime 2e-11).
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 -noRun > ../a1.log 2>&1 & p1=$!; sleep 0.5; ./Allrun $PREV -endTime 2e-9 -noRun > ../a2.log 2>&1 & p2=$!
wait $p1; r1=$?; wait $p2; r2=$?; echo "   first rc=$r1: $(grep -a -i 'refus\|in use\|error\|running' ../a1.log | head -2 | cut -c1-200 | tr '\n' '|')"; echo "   second rc=$r2: $(grep -a -i 'refus\|in use\|error\|running' ../a2.log | head -2 | cut -c1-200 | tr '\n' '|')"
tryt 200 "third Allrun -noRun" ./Allrun $PREV -endTime 2e-9 -noRun; tail -3 $W/try.log | cut -c1-200
blastEnd 2e-11 1e-11; tryt 200 "cellBlastFoam to 2e-11" cellBlastFoam; tail -2 $W/try.log | cut -c1-150; after
