#!/bin/bash
# f29 (class 2, an interrupted calibration over a user's earlier result): the calibration case holding an earlier constant/solidProperties.calibrated and postProcessing/calibration/results.md (a user's: "mine"); calibrateCell SIGTERMed after 40 s: both files unchanged, exit 128+15 or an error, no forward run left running.
. "$(dirname "$0")/../lib.sh"
cal; mkdir -p postProcessing/calibration; echo "mine: earlier result" > constant/solidProperties.calibrated; echo "mine: earlier report" > postProcessing/calibration/results.md
calibrateCell > ../log.c 2>&1 & p=$!; sleep 40; kill -TERM $p; wait $p; echo "   calibrateCell rc=$?"; tail -2 ../log.c | cut -c1-200
sleep 2; kept "mine: earlier result" "mine: earlier report"; echo "   left running: $(inDir $W | cut -c1-200)"; killIn $W
