#!/bin/bash
# f46 (class 6, cellMesh's maxElements at its exact bound): the indentation cell with maxElements 1: refused naming the count N; then maxElements N: accepted (meshed); N-1: refused naming maxElements, N and the limit.
. "$(dirname "$0")/../lib.sh"
ind; cp system/cellMeshDict ../m0; echo "maxElements 1;" >> system/cellMeshDict; tryt 60 "maxElements 1" cellMesh
N=$(grep -a -o -i 'at least [0-9]\+\|about [0-9]\+\|[0-9]\+ elements' $W/try.log | grep -o '[0-9]\+' | head -1); echo "   N=$N"
for m in $N $((N - 1)); do cp ../m0 system/cellMeshDict; echo "maxElements $m;" >> system/cellMeshDict; rm -f constant/cell.msh; tryt 60 "maxElements $m" cellMesh; ls constant/cell.msh 2>/dev/null; done
