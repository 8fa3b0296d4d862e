#!/bin/bash
# x47: a finished blast preview Allrun run AGAIN with the same options (the user forgot it ran): restore0Dir rewrites 0/ of a case with results, steps skipped: exit 0, nothing lost, and a later restart (latestTime, 10 ns) still accepted?
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1; snap ../s0; ls -a 0 | tr '\n' ' '; echo
run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a2 2>&1; tail -2 ../log.a2 | cut -c1-200; echo "lost: $(gone ../s0 | tr '\n' ' ')"; ls -a 0 | tr '\n' ' '; echo
latest; printf 'endTime 3e-9;\nwriteInterval 1e-9;\n' > system/controlDict.allrun; run 100 cellBlastFoam > log.r 2>&1; tail -1 log.r; fatal log.r 4
