#!/bin/bash
# i12 (class 1/SILENT, exact restart with the extrapolated predictor): xbd (Allrun -predictor extrapolated, 14 um column, run
# to 5e-9: the pulse on the cell from about 4 ns) restarted to 6e-9, against a straight run of the same case from 0 to 6e-9:
# kill-and-restart is exact, so the four logs joined over restarts, solid.h5 and 6e-09/p are bitwise the same. A difference
# means the restart state lacks what the predictor extrapolates from (a_n-1).
. "$(dirname "$0")/../lib.sh"
xbd; fresh; e6; tryt 500 "straight 0 -> 6e-9" cellBlastFoam; away straight
xbd; rs6; tryt 500 "restart 5e-9 -> 6e-9" cellBlastFoam; cont; cmp6 $W/straight; after
echo "   coupling passes: straight $(tail -1 $W/straight/postProcessing/fsi/0/coupling.dat | cut -c1-120), restarted $(tail -1 postProcessing/fsi/5e-09/coupling.dat 2>/dev/null | cut -c1-120)"
