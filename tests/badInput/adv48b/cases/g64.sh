#!/bin/bash
# g64 (class 4/6, numbers at a double's edges in the solid's law) the prepared preview, endTime 2e-11, constant/solidProperties d0 (the membrane's 2/K, 1/Pa) set to -1.7976931348623157e308 (-DBL_MAX, the solid's 'not a number' sentinel), 1.7976931348623157e308, 1.0000000000000001e-300 (just above OpenFOAM's reader's floor: K = 2e300 Pa, a sound speed of ~1e148 m/s), 9.5125e-310 (subnormal): each refused before the run naming the entry, the value with its digits and the range, or (the floor case) refused for the step count it means; never a floating-point exception, never a run that cannot end (60 s each).
. "$(dirname "$0")/../lib.sh"
blast; short
each constant/solidProperties "d0 -1.7976931348623157e308" "d0 1.7976931348623157e308" "d0 1.0000000000000001e-300" "d0 9.5125e-310" -- cellBlastFoam
