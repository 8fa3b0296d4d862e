#!/bin/bash
# x62: indenterProperties at edges never tried: a hold row of 1e300 s (resource: steps of maxDeltaT 5 s), maxDeltaT 1e300, holdGrowth 1 (no growth), holdDeltaT0 1e-300, a load row with rate 1e300 m/s, radius 1e-3 (a 2-mm bead on a 17-um cell)
. "$(dirname "$0")/../lib.sh"
ind; f=constant/indenterProperties; cp $f ../ip0
sed -i 's/^\(\s*(B\s\+hold\s\+0\s\+\)[0-9.e+-]*)/\11e300)/' $f; grep -a "(B" $f; try "hold 1e300 s" cellIndentationFoam; rm -rf postProcessing; cp ../ip0 $f
each $f "maxDeltaT 1e300" "holdGrowth 1" "holdDeltaT0 1e-300" "radius 1e-3" -- cellIndentationFoam
sed -i '0,/^\(\s*(A\s\+load\s\+\)[0-9.e+-]*/s//\11e300/' $f; grep -a "(A" $f; try "load rate 1e300" cellIndentationFoam
