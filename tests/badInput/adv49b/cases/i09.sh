#!/bin/bash
# i09 (class 1, the newest fsiProperties entries changed between a run and its restart): the finished preview bd (2e-9,
# centralDifference, solidSubcycles 1, motionDistance 5e-6) restarted to 3e-9 after ONE edit each, from a fresh copy:
# coupling{} predictor extrapolated; solidSubcycles 2; interface{} motionDistance 4e-6; motionNearest 4. Each refused before
# anything is written, naming constant/fsiProperties and the entry (coupling/predictor ...), nothing changed.
. "$(dirname "$0")/../lib.sh"
for e in "predictor extrapolated" "solidSubcycles 2" "motionDistance 4e-6" "motionNearest 4"; do
  bd; rs; fsiSet $e; sums > ../s0; tryt 300 "restart with $e" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; cd $W; rm -rf $W/blast; done
