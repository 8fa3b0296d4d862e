#!/bin/bash
# k27 (class 4, fsiProperties interface{} at its edges): short preview: mapTolerance 0, -0, 1e300; motionNearest 0, 1, 8.0, 2147483648; motionDistance 0, -0, 4.9e-324, 1e-300, 1.0000000000000001e-300, 1 (1 m: every point of the 20 um column), 1e300. Expected: the invalid ones refused naming interface/<entry>, the value as written and the range; 4.9e-324 and 1e-300 named as what OpenFOAM reads as 0; 1 m accepted (every point moves) or refused naming a bound; nothing written on refusal.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/fsiProperties
vals $F mapTolerance 0 -0 1e300 -- cellBlastFoam
vals $F motionNearest 0 1 8.0 2147483648 -- cellBlastFoam
vals $F motionDistance 0 -0 4.9e-324 1e-300 1.0000000000000001e-300 1 1e300 -- cellBlastFoam
