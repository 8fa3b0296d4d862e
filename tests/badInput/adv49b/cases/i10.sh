#!/bin/bash
# i10 (class 1, a run with the extrapolated predictor continued with the other one): xbd (Allrun -predictor extrapolated,
# written to constant/fsiProperties.allrun, run to 5e-9) restarted to 6e-9 (a) with the .allrun's predictor set to
# centralDifference, (b) with the .allrun file removed (the default predictor); each refused naming constant/fsiProperties
# (or its .allrun) and the entry predictor, nothing changed; (c) unchanged: continues, exit 0.
. "$(dirname "$0")/../lib.sh"
xbd; rs6; echo "   fsiProperties.allrun: $(tr '\n' ' ' < constant/fsiProperties.allrun)"; sed -i 's/extrapolated/centralDifference/' constant/fsiProperties.allrun; sums > ../s0
tryt 300 "(a) .allrun predictor centralDifference" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
sed -i 's/centralDifference/extrapolated/' constant/fsiProperties.allrun; mv constant/fsiProperties.allrun ../fa; sums > ../s0
tryt 300 "(b) fsiProperties.allrun removed" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
mv ../fa constant/fsiProperties.allrun; tryt 300 "(c) unchanged" cellBlastFoam; cont; after
