#!/bin/bash
# g63 (class 4, g31/g32 carried past the pulse's arrival: motion bands valid alone) the prepared preview (20 um column: the pulse reaches the cell at about 8 ns) run to 1.2e-8 with motionDistance 5e-6 (B, the default), 1e-12 (no fluid point off the interface in the band) and 1 (1 m, every point): the probes' logs against B. Expected: 1e-12 refused before the run, or its results within the mesh-motion's own error of B (said); 1 m the same as B to the scheme's accuracy, or refused.
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1.2e-8 6e-9; mv $W/blast $W/B; cd $W/B; tryt 400 "B default 5e-6" cellBlastFoam
for m in 1e-12 1; do blast; blastEnd 1.2e-8 6e-9; sete constant/fsiProperties motionDistance $m; tryt 400 "motionDistance $m" cellBlastFoam; tail -1 $W/try.log | cut -c1-100; closeTo $W/B; mv $W/blast $W/m$m; done
