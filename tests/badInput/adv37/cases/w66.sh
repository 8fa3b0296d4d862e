#!/bin/bash
# w66: calibrationDict entries at the edges: tolerance nan, finiteDifferenceStep 0, relativeError -0.05, maxIterations 0, a parameter with min > max, a value outside [min, max], a target value 0, a target peak that is not in the protocol (endZ)
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../orig; d=system/calibrationDict
for e in "tolerance nan" "finiteDifferenceStep 0" "relativeError -0.05" "maxIterations 0"; do cp ../orig $d; sed -i "s/^${e%% *} .*/${e%% *} ${e#* };/" $d; try "$e" calibrateCell -case .; done
cp ../orig $d; sed -i 's/        min     0.01;/        min     30;/' $d; try "min>max" calibrateCell -case .
cp ../orig $d; sed -i 's/        value   1.67; /        value   50; /' $d; try "value>max" calibrateCell -case .
cp ../orig $d; sed -i 's/F_B { peak endB; value 0.3e-9; }/F_B { peak endB; value 0; }/' $d; try "target 0" calibrateCell -case .
cp ../orig $d; sed -i 's/F_B { peak endB;/F_B { peak endZ;/' $d; try "peak endZ" calibrateCell -case .
