#!/bin/bash
# k04 (class 4, the new keywords misspelt or twice): structuredSmoothings elliptic; structuredsmoothing elliptic; (b) structuredSmoothing given twice in cellMeshDict itself (not through .allrun), (c) hexCoeffs { oGrid orthogonal; ogrid orthogonal; } and oGrid twice in hexCoeffs. Expected: unknown keyword with the closest valid one / given twice naming both places; nothing written.
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusShape scaledCell; mv_ structuredSmoothings elliptic; mv_ structuredsmoothing elliptic
cp system/cellMeshDict $W/cmd; sed -i 's/^mode /structuredSmoothing elliptic;\nstructuredSmoothing none;\nmode /' system/cellMeshDict; cmk "(b) twice in cellMeshDict"; cp $W/cmd system/cellMeshDict
qm "" "oGrid orthogonal; ogrid orthogonal;"; cmk "(c1) oGrid + ogrid"
qm "" "oGrid orthogonal; oGrid straight;"; cmk "(c2) oGrid twice"
