#!/bin/bash
# w15: blast run to 2 ns, then constant/thermophysicalProperties C0 1450 -> 1500 (the water's law), restart with latestTime to 3 ns: refused naming the file?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/^\( *C0 *\)1450;/\11500;/' constant/thermophysicalProperties; grep -n "C0 " constant/thermophysicalProperties
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r
