#!/bin/bash
# k19 (class 3, checkQuarterRun.sh while the quarter runs): q restarted to 6e-9 on 2 ranks in the background; while it runs, checkQuarterRun.sh on it. Expected: refused or failed naming the run as running/unfinished, the run undisturbed (it ends rc 0, its logs continuous); never exit 0. (P1b: the run writes log.cellBlastFoam, as the Allrun does)
. "$(dirname "$0")/../lib.sh"
q; latest; qEnd 6e-9; (qrun 2 > log.cellBlastFoam 2>&1) & p=$!; waitFor 60 test -f .runLock; sleep 2
tryt 600 "checkQuarterRun while the run goes" bash $ROOT/tests/blast/checkQuarterRun.sh .; tail -3 $W/try.log | cut -c1-200 | sed 's/^/   /'
echo "   run alive after it: $(kill -0 $p 2>/dev/null && echo yes || echo no)"; wait $p; echo "   run rc=$? | $(grep -a -m2 "FATAL\|^End" log.cellBlastFoam | tr '\n' ' ')"; ls -d processor0/[0-9]* | tr '\n' ' '; echo
