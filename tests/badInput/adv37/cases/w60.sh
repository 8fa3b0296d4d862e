#!/bin/bash
# w60: pulseStudy sampleInterval and strainRateWindow at the edges: sampleInterval 0, -0.5e-9, 1e300; strainRateWindow 0, nan
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../orig; for e in "sampleInterval 0" "sampleInterval -0.5e-9" "sampleInterval 1e300" "strainRateWindow 0" "strainRateWindow nan"; do cp ../orig system/pulseStudyDict; setStudy "${e%% *}" "${e#* }"; try "$e" pulseStudy -case .; done
