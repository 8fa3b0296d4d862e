#!/bin/bash
# w109: calibrateCell (maxIterations 1, -nProcs 1) SIGKILLed 15 s in, its forward run left running as an orphan in the -work folder; the same command again at once, to its end: two runs in one folder? the fit equal to a clean calibration's?
. "$(dirname "$0")/../lib.sh"
cal; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; cp -r . ../clean
calibrateCell -case . -nProcs 1 -work ../cw > log.1 2>&1 & p=$!; sleep 15; kill -KILL $p; wait $p 2>/dev/null; echo "killed; running under ../cw: $(inDir $W/cw)"
calibrateCell -case . -nProcs 1 -work ../cw > log.2 2>&1 & q=$!; for k in 1 2 3 4; do sleep 4; echo "t+$((4*k)) s, under ../cw: $(inDir $W/cw)"; done; wait $q; echo "second rc=$?"; grep -a -i "C10\|fitted\|result" log.2 | tail -3 | cut -c1-200
(cd ../clean && calibrateCell -case . -nProcs 1 > log.c 2>&1; echo "clean rc=$?"; grep -a -i "C10\|fitted\|result" log.c | tail -3 | cut -c1-200)
