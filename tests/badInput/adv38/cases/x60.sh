#!/bin/bash
# x60: pulseStudyDict entries at edges never tried: sampleInterval 5e-9 (above the 2-ns run), strainRateWindow 1 s, a threshold value -0.1, a threshold indicator 'stress', duration (0.9) (the Allrun's -pulse maximum), nProcs 1e6: refused before any run, naming the entry and range?
. "$(dirname "$0")/../lib.sh"
study; d=system/pulseStudyDict; cp $d ../d0
for e in "sampleInterval 5e-9" "strainRateWindow 1" "duration (0.9)" "nProcs 1e6"; do cp ../d0 $d; setStudy ${e%% *} "${e#* }"; try "$e" timeout 50 pulseStudy; rm -rf postProcessing; done
cp ../d0 $d; sed -i '0,/value       0.21 \[-\];/s//value -0.1 [-];/' $d; try "threshold -0.1" timeout 50 pulseStudy; cp ../d0 $d; sed -i '0,/indicator   strain;/s//indicator stress;/' $d; try "indicator stress" timeout 50 pulseStudy
