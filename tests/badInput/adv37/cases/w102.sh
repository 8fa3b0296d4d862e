#!/bin/bash
# w102: blast, 2 ranks finished (times only in processor*/): solidToFoam writes root time folders <t>/solid; then reconstructPar -newTimes and a serial restart: are the fluid times reconstructed, or skipped as 'existing' and the restart misled?
. "$(dirname "$0")/../lib.sh"
pblastDone; try s2f solidToFoam solid/solid.h5; ls -d [1-9]* | tr '\n' ' '; ls 2e-09 | tr '\n' ' '; echo
reconstructPar -newTimes > log.rec 2>&1; echo "reconstructPar -newTimes rc=$?"; grep -a -i "skip\|already\|exist\|Time = " log.rec | head -4; ls 2e-09 | tr '\n' ' '; echo
latest; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r
