#!/bin/bash
# g31 (class 4, a motion band that holds no fluid point) the prepared preview (blast) with constant/fsiProperties interface/motionDistance 1e-12 m (valid alone: > 0; but below every cell: no fluid point within it but the interface's own), run to 2e-11: refused naming motionDistance (the band holds no point off the interface: the cells next to the cell would be crushed), or run with the mesh valid; never a silent run whose water does not follow the cell.
. "$(dirname "$0")/../lib.sh"
blast; short; sete constant/fsiProperties motionDistance 1e-12; grep -a motionDistance constant/fsiProperties
tryt 200 "motionDistance 1e-12" cellBlastFoam; grep -a -i -m3 'band\|motion\|warn' $W/try.log | cut -c1-200; tail -2 $W/try.log | cut -c1-150; after
