#!/bin/bash
# w31: blast: the 2e-09 time directory (with its marker) swapped for the 2e-09 of a 30 MPa run of the same case, restart: refused?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; cd ..; cp -r blast other; cd other; rm -rf 1e-09 2e-09 solid postProcessing; sed -i 's/50000000/30000000/g' 0/p; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; cellBlastFoam > log.o 2>&1; echo "other rc=$?"
cd ../blast; rm -rf 2e-09; cp -a ../other/2e-09 .; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
