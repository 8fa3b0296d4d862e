#!/bin/bash
# y02: preview Allrun run to its end at 2 ns; then ./Allrun again with -endTime 4e-9 (a longer run asked): the solver run/continued, or skipped as "already run" with the results at 2 ns and exit 0 (said?)
. "$(dirname "$0")/../lib.sh"
prev; run 200 ./Allrun $PREV -endTime 2e-9 > ../log.a1 2>&1; echo "first: times $(ls -d [1-9]* | tr '\n' ' ')"
run 200 ./Allrun $PREV -endTime 4e-9 > ../log.a2 2>&1; echo "second Allrun -endTime 4e-9: $(grep -a -i "already\|error\|refus\|endTime" ../log.a2 | head -3 | cut -c1-220 | tr '\n' '|')"; echo "times: $(ls -d [1-9]* | tr '\n' ' ')"
