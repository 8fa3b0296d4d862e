#!/bin/bash
# g01 (class 1, what a restart reads beyond the fields: uniform/time) A = bd with 2e-09/uniform/time's value changed to 2.5e-09 (directory name and every field kept), restart latestTime to 3e-9; B = the clean restart. Expected: refused naming 2e-09/uniform/time (its bytes are not its commit's), nothing written; or A continues exactly as B; never a time line shifted by 0.5 ns.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B clean restart" cellBlastFoam
bd; rs; sed -i 's/^\(value *\)[-+0-9.eE]* *;/\12.5e-09;/' 2e-09/uniform/time; grep -a '^value' 2e-09/uniform/time; sums > ../s0
tryt 240 "A: uniform/time value 2.5e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
