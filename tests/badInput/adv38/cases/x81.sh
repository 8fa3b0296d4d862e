#!/bin/bash
# x81 (phase 2): the plain restart of an UNCHANGED finished blast case (serial, startFrom latestTime, endTime 3 ns), and sod's rhoRiemannFoam restart: continued, or refused?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; run 100 cellBlastFoam > log.r 2>&1; fatal log.r 9; echo "serial times: $(ls -d [1-9]* | tr '\n' ' ')"
sodDone; e=$(sed -n "s/^endTime *\([^;]*\);.*/\1/p" system/riemannProblemDict); sed -i "s/^endTime .*/endTime $(/usr/bin/python3 -c "print($e*1.2)");/; s/^startFrom .*/startFrom latestTime;/" system/controlDict; run 100 rhoRiemannFoam > log.r 2>&1; fatal log.r 4; echo "sod times: $(ls -d [1-9]* 0.[0-9]* 2>/dev/null | tr '\n' ' ')"
