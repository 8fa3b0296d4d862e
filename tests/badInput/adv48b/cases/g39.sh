#!/bin/bash
# g39 (class 4, near-miss words of the coupling's enumerations) the prepared preview, endTime 2e-11, constant/fsiProperties coupling: scheme Robin, IQN-ILS, iqnils, robin_; onNonConvergence Stop, warning; predictor centraldifference, extrapolate; load Pressure: each refused before the run naming the file, the entry, the value, the valid words and the closest one.
. "$(dirname "$0")/../lib.sh"
blast; short
each constant/fsiProperties "scheme Robin" "scheme IQN-ILS" "scheme iqnils" "scheme robin_" "onNonConvergence Stop" "onNonConvergence warning" "predictor centraldifference" "predictor extrapolate" "load Pressure" -- cellBlastFoam
