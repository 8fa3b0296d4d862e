#!/bin/bash
# g40 (class 4, the coupling's numbers at their edges) the prepared preview, endTime 2e-11, constant/fsiProperties: maxIter 0, 2147483648, 1.5; tolerance 0, 1; velocityScale 0, -0; solidSubcycles 1001, 1000.0000000000001, 0; motionNearest 0, 2147483647; mapTolerance 0, inf: each refused before the run naming the entry, the value with the digits that show why, and the valid range; accepted only inside it.
. "$(dirname "$0")/../lib.sh"
blast; short
each constant/fsiProperties "maxIter 0" "maxIter 2147483648" "maxIter 1.5" "tolerance 0" "tolerance 1" "velocityScale 0" "velocityScale -0" "solidSubcycles 1001" "solidSubcycles 1000.0000000000001" "solidSubcycles 0" "motionNearest 0" "motionNearest 2147483647" "mapTolerance 0" "mapTolerance inf" -- cellBlastFoam
