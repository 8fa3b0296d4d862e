#!/bin/bash
# k54 (class 1, the coupling predictor changed between a finished run and its restart): bd (centralDifference), predictor extrapolated added to coupling{}, restart to 3e-9; (b) solidSubcycles 1 -> 4. Expected: refused naming constant/fsiProperties and coupling/predictor (solidSubcycles), nothing written; or, for the predictor, the documented warning that the first step takes centralDifference, with the input record's verdict said.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp constant/fsiProperties $W/f0; sums > ../s0
fsiSet predictor extrapolated > /dev/null; tryt 200 "(a) predictor -> extrapolated" cellBlastFoam; cont; grep -a -i -m2 'warn\|predictor' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; echo "   changed: $(changed ../s0)"; cp $W/f0 constant/fsiProperties; rm -rf 3e-09
sete constant/fsiProperties solidSubcycles 4 > /dev/null; sums > ../s0; tryt 200 "(b) solidSubcycles 1 -> 4" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
