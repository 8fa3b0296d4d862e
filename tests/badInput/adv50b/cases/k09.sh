#!/bin/bash
# k09 (class 4, oGrid values): hexCoeffs oGrid Orthogonal, orthognal, 1, yes, "orthogonal straight", an empty value, and oGrid orthogonal with a unit [m] on the quarter's hexahedral water. Expected: each refused naming the file, hexCoeffs/oGrid, the valid words (straight orthogonal) and the closest; meshes of the good run kept.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null; echo "   good run: $(msh)"
for v in Orthogonal orthognal 1 yes "orthogonal straight" "" "orthogonal [m]"; do qm "" "oGrid $v;"; cmk "oGrid '$v'"; done
