#!/bin/bash
# w24: blast: solid/solid.h5 of a finished 50 MPa run replaced by the one of a 30 MPa run of the same case (same mesh, same steps), restart: refused?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cd ..; cp -r blast other; cd other; rm -rf 1e-09 2e-09 solid postProcessing; sed -i 's/50000000/30000000/g' 0/p; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; blastEnd 2e-9 1e-9; cellBlastFoam > log.o 2>&1; echo "other rc=$?"
cd ../blast; cp ../other/solid/solid.h5 solid/solid.h5; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
