#!/bin/bash
# y14: Allrun -pulse at odd values (fix19t: times written with repr): -pulse 1e-10 (= the ramp), 1.23456789012345e-9, 3e-9 with -endTime 2e-9, -pulse 0; -noRun: 0/p's table rows increasing and exact, or refused naming -pulse and its range
. "$(dirname "$0")/../lib.sh"
for v in 1e-10 1.23456789012345e-9 0 2e-10; do prev; run 60 ./Allrun $PREV -endTime 2e-9 -pulse $v -noRun > ../log.n 2>&1; echo "-pulse $v: $(grep -a -i -m1 "error\|pulse" ../log.n | cut -c1-200) | rows: $(sed -n '/uniformValue/,/);/p' 0/p 2>/dev/null | grep -a '^ *(' | tr -s ' \n' ' ')"; cd $W; rm -rf $W/c; done
