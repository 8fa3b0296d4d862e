#!/bin/bash
# k45 (class 6, the orthogonal O-grid's cost at the tutorial's default water): quarter3D with the tutorial's fluid (box 100 um, near 0.5, axial 0.5, lateral 1, far 5 um: 129,499 hexahedra, below the default maxCells 1e6), straight then oGrid orthogonal (Gauss-Seidel sweeps, at most 300). Expected: both end within 480 s each with their memory printed (maxRSS), the orthogonal one naming its sweeps; or refused up front; never only ended by the KILL timeout without a word of progress. The ratio of the two CPU times is the figure (load printed).
. "$(dirname "$0")/../lib.sh"
mdir quarter3D; printf 'nucleusSize 1.4e-6;\ncytoplasmSize 1.4e-6;\nmembraneSize 1e-6;\n' > system/cellMeshDict.allrun; uptime
cm "" 480; grep -a -i -m1 'hexahedra' $W/try.log | cut -c1-160
echo 'fluid { hexCoeffs { oGrid orthogonal; } }' >> system/cellMeshDict.allrun; cm "" 480; grep -a -i -m2 'hexahedra\|sweep' $W/try.log | cut -c1-160; tail -2 $W/try.log | cut -c1-160; uptime
