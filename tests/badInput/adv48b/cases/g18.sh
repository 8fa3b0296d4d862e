#!/bin/bash
# g18 (class 1, an empty later time made by the user) bd with an empty directory 2.5e-09 (mkdir by hand), restart latestTime to 3e-9: refused naming 2.5e-09 (no fields, no commit marker) or continued from 2e-09 exactly as B with 2.5e-09 named; never a crash, never a "cannot find file" with no hint.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B clean restart" cellBlastFoam
bd; rs; mkdir 2.5e-09; sums > ../s0
tryt 240 "empty 2.5e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
