#!/bin/bash
# k25 (class 4, the hex water's ranges at their edges): topRounding 5 (edge), 4.999999999999999, 100 (edge), 100.00000000000001, 6.0; maxCells 0, 1e9 (edge), 1000000001, 1e5 (real); farSize = L/4 = 7.5e-6 (edge) and 7.5000000000000009e-06; lateralSize = farSize (edge) and farSize + 1 ulp. Expected: edges meshed (or refused for another named reason), beyond-edge values refused with digits that show them outside the range; meshes kept on refusal.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null
for v in 5 4.999999999999999 100 100.00000000000001 6.0; do qm "" "topRounding $v;"; cmk "topRounding $v" "" 300; done
for v in 0 1e9 1000000001 1e5; do qm "" "maxCells $v;"; cmk "hexCoeffs maxCells $v"; done
for v in 7.5e-6 7.5000000000000009e-06; do qm "farSize $v;"; cmk "farSize $v" "" 300; done
for v in 5e-6 5.000000000000001e-06; do qm "" "lateralSize $v;"; cmk "lateralSize $v (farSize 5e-6)" "" 300; done
