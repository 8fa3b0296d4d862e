#!/bin/bash
# x20: blast 0/p with OpenFOAM's standard '#includeEtc "caseDicts/setConstraintTypes"' in boundaryField (patch groups cyclic, wedge, empty, ... as patterns): a fresh run accepted (no false duplicate)? and 0/T with #includeEtc beside its ".*" pattern?
. "$(dirname "$0")/../lib.sh"
blast; sed -i '0,/^{/!{0,/^{/s//{\n    #includeEtc "caseDicts\/setConstraintTypes"/}' 0/p; sed -n '/boundaryField/,/top/p' 0/p | head -5
try "0/p includeEtc" cellBlastFoam; rm -rf [1-9]* solid postProcessing
sed -i '0,/^{/!{0,/^{/s//{\n    #includeEtc "caseDicts\/setConstraintTypes"/}' 0/T; try "0/p and 0/T includeEtc" cellBlastFoam
