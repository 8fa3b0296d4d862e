#!/bin/bash
# f30 (class 4, a calibration target at the edges): calibrationDict targets F_B value 4.9e-324, 1e-300, 0, -0 (sigma = relativeError x target: 0 or below OpenFOAM's reader): each refused before any forward run naming targets/F_B/value and the range; never a fit run with a zero or subnormal sigma.
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../c0
for v in 4.9e-324 1e-300 0 -0; do cp ../c0 system/calibrationDict; sed -i "s/F_B { peak endB; value 0.3e-9; }/F_B { peak endB; value $v; }/" system/calibrationDict; n=$(grep -c "value $v; }" system/calibrationDict)
  tryt 45 "F_B value $v (edit $n)" calibrateCell; echo "   ran: $(grep -a -c -i 'iteration\|forward' $W/try.log) progress lines"; killIn $W; done
