#!/bin/bash
# i13 (class 1/SILENT, exact restart with solid subcycles): mbd (Allrun -membraneLayers 2 -solidSubcycles 4: the membrane's
# 100 nm elements make the solid's stable step the smaller one, so the coupled step takes several solid substeps; run to
# 5e-9, the cell loaded from about 4 ns) restarted to 6e-9, against a straight run from 0 to 6e-9: bitwise the same logs,
# solid.h5 and 6e-09/p (the step's start force f_n is in uniform/solidState). Also shown: the coupled dt against the solid's
# (the subcycles are active).
. "$(dirname "$0")/../lib.sh"
mbd; fresh; e6; tryt 500 "straight 0 -> 6e-9" cellBlastFoam; grep -a -i -m3 'subcycl\|stable' $W/try.log | cut -c1-200 | sed 's/^/   /'; away straight
mbd; rs6; tryt 500 "restart 5e-9 -> 6e-9" cellBlastFoam; cont; cmp6 $W/straight; after
