#!/bin/bash
# k36 (class 1, the band motion changed between a finished run and its restart): bd (motionDistance 5e-6, finished at 2e-9): (a) motionDistance 4e-6 in constant/fsiProperties, restart to 3e-9; (b) motionDistance 4e-6 in a new constant/fsiProperties.allrun (the file the fsiProperties #sincludes, as Allrun -motionDistance writes it); (c) motionNearest 8 -> 6. Expected: each refused before writing anything, naming constant/fsiProperties, interface/motionDistance (motionNearest) and, for (b), the included file; nothing changed.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp constant/fsiProperties $W/f0; sums > ../s0
sete constant/fsiProperties motionDistance 4e-6 > /dev/null; tryt 200 "(a) motionDistance 5e-6 -> 4e-6" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; cp $W/f0 constant/fsiProperties
echo 'interface { motionDistance 4e-6; }' > constant/fsiProperties.allrun; sums > ../s0; tryt 200 "(b) motionDistance 4e-6 in fsiProperties.allrun" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; rm -f constant/fsiProperties.allrun
sete constant/fsiProperties motionNearest 6 > /dev/null; sums > ../s0; tryt 200 "(c) motionNearest 8 -> 6" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; cp $W/f0 constant/fsiProperties; after
