#!/bin/bash
# w71: blast controlDict values at the edges: deltaT 0, deltaT -1e-12, maxDeltaT 0, maxCo 0, maxCo -0.5, maxCo nan, maxCo 1e300, endTime 2e-9s, writeInterval -1e-9, purgeWrite -1, writePrecision 0
. "$(dirname "$0")/../lib.sh"
blast; each system/controlDict "deltaT 0" "deltaT -1e-12" "maxDeltaT 0" "maxCo 0" "maxCo -0.5" "maxCo nan" "maxCo 1e300" "purgeWrite -1" "writePrecision 0" -- cellBlastFoam
echo 'endTime 2e-9s;' > system/controlDict.allrun; try "endTime 2e-9s" cellBlastFoam; printf 'endTime 2e-9;\nwriteInterval -1e-9;\n' > system/controlDict.allrun; try "writeInterval -1e-9" cellBlastFoam; ls | grep -c "^[1-9]"
