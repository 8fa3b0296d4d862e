#!/bin/bash
# z18: calibrationDict edges never tried: relativeError 0 (sigma = 0: the covariance divides by it), relativeError 1e300, covariance 'unscaledd' (misspelt), maxIterations 1e6 (resource), a target with value 0 N: refused before any forward run (within 60 s), naming entry and range?
. "$(dirname "$0")/../lib.sh"
cal; D=system/calibrationDict; cp $D ../orig
for e in "relativeError 0" "relativeError 1e300" "covariance unscaledd" "maxIterations 1e6"; do cp ../orig $D; k=${e%% *}; v=${e#* }; sed -i "s/^$k .*/$k $v;/" $D; try "$e" calibrateCell -work $W/work_${k}; rm -rf $W/work_*; done
cp ../orig $D; sed -i 's/F_B { peak endB; value 0.3e-9; }/F_B { peak endB; value 0; }/' $D; grep -c 'value 0; }' $D; try "target F_B value 0" calibrateCell -work $W/work_t0
echo "left in the case: $(ls | tr '\n' ' ')"
