#!/bin/bash
# f66 (class 4, a strain-rate window one rounding away from a whole number of samples): pulseStudy with sampleInterval 3.3333333333333335e-10 (1e-9/3 in double: 1e-9 / it = 2.9999999999999996) and strainRateWindow 1e-9, nProcs 2 on the one-point grid (so that the study stops at nProcs if the window is taken): the window accepted as 3 samples (the refusal names nProcs only) or refused naming both entries with the ratio; then sampleInterval 3.4e-10 (2.94 samples): refused naming strainRateWindow.
. "$(dirname "$0")/../lib.sh"
study; /usr/bin/python3 -c "print('   1e-9 / (1e-9/3) =', repr(1e-9 / (1e-9/3)), ' 1e-9/3 =', repr(1e-9/3))"; setStudy nProcs 2
setStudy sampleInterval 3.3333333333333335e-10; tryt 60 "(a) sampleInterval 1e-9/3" pulseStudy
setStudy sampleInterval 3.4e-10; tryt 60 "(b) sampleInterval 3.4e-10" pulseStudy; ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' '; echo
