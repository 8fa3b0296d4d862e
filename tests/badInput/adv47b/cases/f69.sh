#!/bin/bash
# f69 (class 6, pulseStudy's maxPoints at the exact count): a 2 x 2 grid (4 points) with maxPoints 4 and nProcs 5 (so that nothing runs): the refusal names nProcs only (4 runs <= maxPoints 4 accepted); maxPoints 3: refused naming 4 runs and maxPoints 3.
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(20e6 30e6)"; setStudy duration "(2e-9 3e-9)"; setStudy nProcs 5; echo "maxPoints 4;" >> system/pulseStudyDict; tryt 60 "(a) 4 points, maxPoints 4" pulseStudy
sed -i 's/^maxPoints 4;/maxPoints 3;/' system/pulseStudyDict; tryt 60 "(b) 4 points, maxPoints 3" pulseStudy; ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' '; echo
