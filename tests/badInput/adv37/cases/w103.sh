#!/bin/bash
# w103: calibrateCell SIGKILLed 15 s into its forward runs (-nProcs 1, -work W), then run again with the same -work: resumed, started over, or refused with a clear message? left-over processes?
. "$(dirname "$0")/../lib.sh"
cal; calibrateCell -case . -nProcs 1 -work ../cw > log.1 2>&1 & p=$!; sleep 15; kill -KILL $p; wait $p 2>/dev/null; echo "killed; still running under ../cw: $(inDir $W/cw)"; ls -a ../cw | head -8 | tr '\n' ' '; echo
timeout -s TERM 25 calibrateCell -case . -nProcs 1 -work ../cw > log.2 2>&1; echo "second rc=$? (124: our 25 s limit)"; fatal log.2 3; head -3 log.2 | cut -c1-200; sleep 1; echo "left running: $(inDir $W/cw)"
