#!/bin/bash
# g16 (class 1/3, solid.h5 newer than the time directories, then solidToFoam) bd with 2e-09 deleted (solid.h5 and the logs reach 2e-09), solidToFoam solid/solid.h5 (writes the solid region's times, here 2e-09 again), then the restart latestTime to 3e-9: refused naming 2e-09 (solidToFoam's time holds no fluid state) or continued from 1e-09 exactly as B (the same case restarted without solidToFoam); never a crash, never rows of both.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; rm -rf 2e-09; tryt 240 "B: 2e-09 deleted, restart" cellBlastFoam
bd; rs; rm -rf 2e-09; tryt 120 "solidToFoam" solidToFoam solid/solid.h5; echo "   times after solidToFoam: $(ls -d [0-9]* | tr '\n' ' ')"; ls 2e-09 2>/dev/null | tr '\n' ' '; echo; sums > ../s0
tryt 240 "restart after solidToFoam" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
