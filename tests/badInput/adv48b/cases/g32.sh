#!/bin/bash
# g32 (class 4, a motion band larger than the domain) the prepared preview with motionDistance 1 (1 m, the domain is 50 um x 20 um): every fluid point follows the cell, also the far walls' points (they would leave their planes). Expected: refused naming motionDistance and the domain's size, or clamped (said) and run to 2e-11 with the walls' points kept on their walls; compared with the default 5e-6 run (the probes' pressures at 2e-11).
. "$(dirname "$0")/../lib.sh"
blast; short; mv $W/blast $W/B; cd $W/B; tryt 200 "B default 5e-6" cellBlastFoam
blast; short; sete constant/fsiProperties motionDistance 1; tryt 200 "motionDistance 1 m" cellBlastFoam; grep -a -i -m3 'band\|motion\|warn' $W/try.log | cut -c1-200; tail -2 $W/try.log | cut -c1-150; after
[ -d 2e-11 ] && { closeTo $W/B; for t in 1e-11 2e-11; do cmp -s $t/polyMesh/points $W/B/$t/polyMesh/points && echo "   $t points same as B" || echo "   $t points differ from B"; done; }
