#!/bin/bash
# x82 (phase 2): the plain restart of an UNCHANGED finished 2-rank blast case (startFrom latestTime, endTime 3 ns, mpirun -np 2): continued, or refused as x81?
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; run 100 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 5; echo "2-rank times: $(ls -d processor1/[1-9]* | tr '\n' ' ')"
