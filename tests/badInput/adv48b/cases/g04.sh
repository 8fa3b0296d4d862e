#!/bin/bash
# g04 (class 1, the moved mesh) bd with 2e-09/polyMesh/points replaced by 1e-09/polyMesh/points (another time's moved mesh, a valid file), restart latestTime to 3e-9: refused naming 2e-09/polyMesh/points, nothing written.
. "$(dirname "$0")/../lib.sh"
bd; rs; ls 2e-09/polyMesh; cmp -s 1e-09/polyMesh/points 2e-09/polyMesh/points && echo "   (points of 1e-09 and 2e-09 equal already)"; cp 1e-09/polyMesh/points 2e-09/polyMesh/points; sums > ../s0
tryt 240 "2e-09 points of 1e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
