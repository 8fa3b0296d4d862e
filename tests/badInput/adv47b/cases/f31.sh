#!/bin/bash
# f31 (class 4, a parameter's bounds): calibrationDict cytoplasm.C10: (a) value 20.000000000000004 with max 20 (one ulp beyond): refused naming value and [min, max]; (b) min 0.01 max 0.01 (an empty interval): refused naming min/max; (c) value 20 (the bound): accepted (forward runs start within 45 s).
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../c0
sed -i "0,/value   1.67;/s//value   20.000000000000004;/" system/calibrationDict; tryt 45 "(a) value one ulp above max" calibrateCell; killIn $W
cp ../c0 system/calibrationDict; sed -i "0,/max     20;/s//max     0.01;/; 0,/value   1.67;/s//value   0.01;/" system/calibrationDict; tryt 45 "(b) min = max = value 0.01" calibrateCell; killIn $W
cp ../c0 system/calibrationDict; sed -i "0,/value   1.67;/s//value   20;/" system/calibrationDict; tryt 45 "(c) value 20 (the bound)" calibrateCell; killIn $W
