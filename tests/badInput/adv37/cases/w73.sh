#!/bin/bash
# w73: fsiProperties values at the edges: maxIter 0, tolerance 0, tolerance nan, velocityScale -1e-2, mapTolerance 0, motionDistance 0, motionNearest 0, solidSubcycles 0, solidSubcycles 1e9, onNonConvergence ignore
. "$(dirname "$0")/../lib.sh"
blast; each constant/fsiProperties "maxIter 0" "tolerance 0" "tolerance nan" "velocityScale -1e-2" "mapTolerance 0" "motionDistance 0" "motionNearest 0" "solidSubcycles 0" "solidSubcycles 1e9" "onNonConvergence ignore" -- cellBlastFoam
