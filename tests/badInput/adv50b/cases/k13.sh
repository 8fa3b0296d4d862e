#!/bin/bash
# k13 (class 4, the water's height with oGrid orthogonal at its lower edge): quarter hex, innerMargin 2e-6 (B = 7.9 + 2 = 9.9 um), axialSize 1 um: height 10.9e-6 (the guide's range (H + innerMargin + axialSize, L]: its open edge, refused), 10.900000000000002e-6 (1 ulp above: meshed, at least one axial layer above the inner box), both with oGrid orthogonal and topRounding 5. Expected: the first refused naming height and the range with digits that show why; the second meshed without an inverted cell or refused naming why; never a crash or hang.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null
qm "height 10.9e-6;" "innerMargin 2e-6; oGrid orthogonal; topRounding 5;"; cmk "(a) height = B + axialSize"
qm "height 1.0900000000000002e-05;" "innerMargin 2e-6; oGrid orthogonal; topRounding 5;"; cmk "(b) height = B + axialSize + 1 ulp" "" 300; grep -a -i -m2 'sweep\|layers\|Jacobian' $W/try.log | cut -c1-160
