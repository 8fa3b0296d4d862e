#!/bin/bash
# g03 (class 1, uniform/time missing) bd with 2e-09/uniform/time deleted, restart latestTime to 3e-9: refused naming the missing file and the marker (the time is incomplete), nothing written; or continued exactly as the clean restart B. Never a crash.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B clean restart" cellBlastFoam
bd; rs; rm 2e-09/uniform/time; sums > ../s0
tryt 240 "2e-09/uniform/time deleted" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
