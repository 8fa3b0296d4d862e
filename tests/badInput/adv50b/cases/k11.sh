#!/bin/bash
# k11 (class 4, values valid alone but not together, hex water): oGrid orthogonal with topRounding 6 and innerMargin = nearSize (1e-6, the range's lower edge), then innerMargin one ulp below nearSize (9.999999999999997e-07: refused with digits that show it). Expected: (a) meshed with no inverted cell (the run says so) and checkMesh's "Mesh OK" after gmshToFoam, or refused naming the entries; (b) refused naming innerMargin and its range.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null
qm "" "oGrid orthogonal; topRounding 6; innerMargin 1e-6;"; cmk "(a) orthogonal + topRounding 6 + innerMargin = nearSize" "" 300; grep -a -i -m3 'sweep\|Jacobian\|hexahedra' $W/try.log | cut -c1-160
if [ -f constant/fluid.msh ]; then timeout 120 gmshToFoam constant/fluid.msh > $W/g2f.log 2>&1; timeout 120 checkMesh > $W/cm.log 2>&1; echo "   checkMesh: $(grep -a -m3 'Mesh OK\|Failed\|non-orthogonality' $W/cm.log | tr '\n' '|' | cut -c1-250)"; fi
qm "" "oGrid orthogonal; topRounding 6; innerMargin 9.999999999999997e-07;"; cmk "(b) innerMargin nearSize - 1 ulp"
