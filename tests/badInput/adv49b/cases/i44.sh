#!/bin/bash
# i44 (class 1/SILENT, planeWave -check on a restarted run): xbd (5e-9) restarted to 6e-9 (its logs in two segments, 0/ and
# 5e-09/) against a straight run 0 -> 6e-9 of the same case (bitwise the same logs, i12): `planeWave -check` prints the same
# errors and verdicts for both (the segments joined); never a check of the first segment only.
. "$(dirname "$0")/../lib.sh"
xbd; fresh; e6; cellBlastFoam > log.straight 2>&1 || echo "straight failed"; tryt 300 "straight: planeWave -check" planeWave -check; cp $W/try.log $W/check.straight; away straight
xbd; rs6; cellBlastFoam > log.restart 2>&1 || echo "restart failed"; tryt 300 "restarted: planeWave -check" planeWave -check; cp $W/try.log $W/check.restart
echo "   check outputs: $(diff <(grep -av 'Time\|[0-9][0-9]:[0-9][0-9]\|/tmp/' $W/check.straight) <(grep -av 'Time\|[0-9][0-9]:[0-9][0-9]\|/tmp/' $W/check.restart) > $W/d.txt && echo same || echo DIFFER)"; head -20 $W/d.txt | cut -c1-200 | sed 's/^/   /'
tail -8 $W/check.restart | cut -c1-200 | sed 's/^/   /'
