#!/bin/bash
# g43 (class 4/6, the hold's step growth at its edges) the smoke indentation (ind) with holdGrowth 0.5, 0.99999999999999989 (one ulp below 1), 0, 1 (valid?), 1.0000000000000002: below 1 the hold's steps shrink and a 1 s hold never ends: refused before the run naming holdGrowth, the value with its digits and the range; 1 and above run (60 s each here).
. "$(dirname "$0")/../lib.sh"
ind; each constant/indenterProperties "holdGrowth 0.5" "holdGrowth 0.99999999999999989" "holdGrowth 0" "holdGrowth 1" "holdGrowth 1.0000000000000002" -- cellIndentationFoam
