#!/bin/bash
# x24: OpenFOAM's #remove directive: fsiProperties 'coupling {...}' then '#remove coupling' and a new 'coupling {...}' (a documented way to replace a dictionary): accepted (no false duplicate) and the new one used? And '#remove' of a keyword then given again in solidProperties.
. "$(dirname "$0")/../lib.sh"
blast; printf '#remove coupling\ncoupling\n{\n    scheme robin; maxIter 12; tolerance 1e-4; velocityScale 1e-2; onNonConvergence warn; solidSubcycles 1;\n}\n' >> constant/fsiProperties
try "#remove coupling + new" cellBlastFoam; echo "  ran to $(ls -d [1-9]* 2>/dev/null | tail -1)"
