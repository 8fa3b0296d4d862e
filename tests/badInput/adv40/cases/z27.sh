#!/bin/bash
# z27: calibration target naming a peak label that appears several times in the protocol's peaks (C1,i: the tutorial's C1 is loaded three times) and one naming a stage that has no peak row of that name (endC1): refused before any forward run (within 60 s), naming the target and the valid labels?
. "$(dirname "$0")/../lib.sh"
cal; D=system/calibrationDict; cp $D ../orig
for l in "C1,i" "endC1" "C1"; do cp ../orig $D; sed -i "s/F_B { peak endB;/F_B { peak $l;/" $D; try "peak $l" calibrateCell -work $W/work_$RANDOM; done
