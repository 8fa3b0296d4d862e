#!/bin/bash
# man-t2.sh (adv51, by hand, phase 2): adv49b i23's first row with its whole log kept: the 2-rank preview of the rebuilt
# bases (/tmp/adv51b-adv47b/pbdBase) restarted to 3e-9 with processor1/2e-09/rho cell 3 = -1 (the case's fset)
cd /work/wt/adv51/tests/badInput; export ADV=/tmp/adv51b-adv51; . adv51/lib.sh; KEEPW=1
pbd; rs; rm -f .runLock; fset processor1/2e-09/rho internal 3 -1
timeout -s KILL 120 mpirun -np 2 cellBlastFoam -parallel > /tmp/adv51-man/t2.log 2>&1; echo "rc $?"; grep -a -n "FATAL\|rank\|cell 3\|another rank" /tmp/adv51-man/t2.log | head -12 | cut -c1-300
cd /; rm -rf "$W"
