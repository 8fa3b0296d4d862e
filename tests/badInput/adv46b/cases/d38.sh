#!/bin/bash
# d38 (class 4, fsiProperties entries misspelt or odd, one at a time on the blast preview, 40 s; the first edit corrected after the first run, its pattern did not match the file): onNonConvergance stop, solidSubcycle 2, motionNearst 4, scheme Robin, maxIter 0, velocityScale 0, mapTolerance -0, solidSubcycles 1.5, coupling given twice: each refused naming the entry (the closest keyword for a misspelling) before the first step.
. "$(dirname "$0")/../lib.sh"
blast; cp constant/fsiProperties ../f
for e in "onNonConvergence warn/onNonConvergance stop" "solidSubcycles  1/solidSubcycle 2" "motionNearest   8/motionNearst 4" "scheme          robin/scheme Robin" "maxIter         30/maxIter 0" "velocityScale   1e-2/velocityScale 0" "mapTolerance    0.1/mapTolerance -0" "solidSubcycles  1/solidSubcycles 1.5"; do cp ../f constant/fsiProperties
  sed -i "s/$e/" constant/fsiProperties; tryt 40 "${e#*/} ($(grep -c "${e#*/}" constant/fsiProperties))" cellBlastFoam; [ -d 1e-09 ] || [ -d solid ] && echo "      (ran)"; rm -rf [1-9]* solid postProcessing; done
cp ../f constant/fsiProperties; echo "coupling { scheme robin; }" >> constant/fsiProperties; tryt 40 "coupling twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing
