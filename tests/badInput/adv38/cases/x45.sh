#!/bin/bash
# x45: after w113's refusal (blast Allrun SIGKILLed in its solver), the user removes log.cellBlastFoam.running only (the advice's '(rm ... first)' read alone) and runs ./Allrun again: the solver skipped and partial results reported as success (w113 again)?
. "$(dirname "$0")/../lib.sh"
prev; setsid ./Allrun $PREV -endTime 8e-9 > ../log.a1 2>&1 & p=$!; waitFor 120 test -d 2e-09; kill -KILL -- -$p; wait $p 2>/dev/null; sleep 0.5
run 100 ./Allrun $PREV -endTime 8e-9 > ../log.a2 2>&1; grep -a "error" ../log.a2 | head -1 | cut -c1-200
rm -f log.cellBlastFoam.running; run 200 ./Allrun $PREV -endTime 8e-9 > ../log.a3 2>&1; echo "third Allrun:"; grep -a -i "already\|error\|refus" ../log.a3 | head -3 | cut -c1-200; tail -1 ../log.a3 | cut -c1-200; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
