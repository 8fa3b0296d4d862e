#!/bin/bash
# x59: fsiProperties (blast) at edges never tried: solidSubcycles 1e6 (resource), maxIter 1, tolerance 0.1 (the upper bound itself), velocityScale 1e300, mapTolerance 1e6, motionDistance 1e-300, axisDirection (0 0 0), axisDirection (1 0 0) (the wrong axis), axisOrigin (1 1 1)
. "$(dirname "$0")/../lib.sh"
blast; f=constant/fsiProperties; o=$(cat $f)
t() { try "$1" cellBlastFoam; rm -rf [1-9]* solid postProcessing; echo "$o" > $f; }
for e in "solidSubcycles  1e6" "maxIter         1" "tolerance       0.1" "velocityScale   1e300"; do k=${e%% *}; sed -i "s/^\(\s*\)$k .*/\1$e;/" $f; t "$e"; done
for e in "mapTolerance    1e6" "motionDistance  1e-300" "axisDirection   (0 0 0)" "axisDirection   (1 0 0)" "axisOrigin      (1 1 1)"; do k=${e%% *}; sed -i "s/^\(\s*\)$k .*/\1$e;/" $f; t "$e"; done
