#!/bin/bash
# f25 (class 4, a step that moves nothing): pulseStudy -dict pulseStudyDict.uncertainty with step 1e-17 and checkStep 2e-17 (in ln p: p e^(1e-17) == p in double, so every linearisation run is the base run and every derivative 0, a half-width of 0) and maxPoints 1 (so that nothing runs): refused naming step (a step that changes no parameter), not only maxPoints.
. "$(dirname "$0")/../lib.sh"
study; cp $ROOT/tutorials/blast/pulseStudy/system/pulseStudyDict.uncertainty system/; sed -i 's/^    step .*/    step        1e-17;/; s/^    checkStep .*/    checkStep   2e-17;/' system/pulseStudyDict.uncertainty; echo "maxPoints 1;" >> system/pulseStudyDict.uncertainty; grep -c 'e-17' system/pulseStudyDict.uncertainty
/usr/bin/python3 -c "import math; print('   0.1788*exp(1e-17) == 0.1788:', 0.1788*math.exp(1e-17) == 0.1788, '; 2.538*exp(-2e-17) == 2.538:', 2.538*math.exp(-2e-17) == 2.538)"
tryt 60 "step 1e-17, maxPoints 1" pulseStudy -dict system/pulseStudyDict.uncertainty; cat $W/try.log | grep -a -i 'step\|maxPoints' | head -4 | cut -c1-250
