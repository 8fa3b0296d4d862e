#!/bin/bash
# g05 (class 1, the moved mesh missing) bd with 2e-09/polyMesh/points deleted (OpenFOAM would read the undeformed constant/polyMesh/points instead), restart latestTime to 3e-9: refused naming the missing points and the marker; never continued on the undeformed mesh (B: the clean restart, compared when A runs).
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B clean restart" cellBlastFoam
bd; rs; rm 2e-09/polyMesh/points; sums > ../s0
tryt 240 "2e-09/polyMesh/points deleted" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d 3e-09 >/dev/null 2>&1 && cmpRef $W/B
