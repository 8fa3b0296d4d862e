#!/bin/bash
# f23 (class 4, one value written two ways): pulseStudy overpressure (10e6 1e7) and duration (2e-9 2.0e-9 0.2e-8): each refused as a value given twice, naming the entry; never two runs of one point or two labels of one value.
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(10e6 1e7)"; tryt 60 "(a) 10e6 and 1e7" pulseStudy
setStudy overpressure "(30e6)"; setStudy duration "(2e-9 2.0e-9 0.2e-8)"; tryt 60 "(b) 2e-9 2.0e-9 0.2e-8" pulseStudy; ls postProcessing/pulseStudy/points 2>/dev/null | tr '\n' ' '; echo
