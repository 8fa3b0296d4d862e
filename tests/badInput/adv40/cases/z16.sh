#!/bin/bash
# z16: planeWave resources: on a finished blast case, -endTime 1 (one second of a 1D column at 50 nm cells: about 1e10 steps) and -dz 1e-11 -endTime 2e-9: refused by -maxSteps / -maxCells naming the option, before computing? within the timeout?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
try "-endTime 1" planeWave -Z 20e-6 -dz 50e-9 -endTime 1; try "-dz 1e-11" planeWave -Z 20e-6 -dz 1e-11 -endTime 2e-9; echo "changed: $(changed ../before)"
