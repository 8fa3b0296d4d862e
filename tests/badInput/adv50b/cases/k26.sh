#!/bin/bash
# k26 (class 4, fsiProperties coupling{} at its edges, integers as reals): a fresh short preview (2e-11 s): maxIter 0, 1, 30.0, 2147483648; tolerance 0, 1e-300, 1.0000000000000001e-300; velocityScale 0, -1; solidSubcycles 1000 (edge: runs), 1001, 1000.0, 1e3. Expected: each refused naming constant/fsiProperties, coupling/<entry>, the value as written and the valid range (whole numbers: "not an integer" as written), nothing written; the edges run.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/fsiProperties
vals $F maxIter 0 1 30.0 2147483648 -- cellBlastFoam
vals $F tolerance 0 1e-300 1.0000000000000001e-300 -- cellBlastFoam
vals $F velocityScale 0 -1 -- cellBlastFoam
vals $F solidSubcycles 1000 1001 1000.0 1e3 -- cellBlastFoam
