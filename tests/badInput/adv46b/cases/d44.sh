#!/bin/bash
# d44 (class 4, pulseStudyDict odd, 40 s each): overpressure (30e6 3e7) (one value twice), duration (2e-9 2.0e-9), nProcs 1.5, sampleInterval 0, strainRateWindow 1.2e-9 (not a whole number of sampleInterval), a threshold value nan [-], a threshold indicator strian: each refused before any point runs, naming the entry.
. "$(dirname "$0")/../lib.sh"
study; cp system/pulseStudyDict ../p
for e in "overpressure (30e6 3e7)" "duration (2e-9 2.0e-9)" "nProcs 1.5" "sampleInterval 0" "strainRateWindow 1.2e-9"; do cp ../p system/pulseStudyDict; setStudy ${e%% *} "${e#* }"; tryt 40 "$e" pulseStudy; echo "      points: $(ls points postProcessing/pulseStudy/points 2>/dev/null | tr "\n" " ")"; rm -rf points postProcessing; done
cp ../p system/pulseStudyDict; sed -i "0,/value       0.21 \[-\];/s//value       nan [-];/" system/pulseStudyDict; tryt 40 "threshold nan" pulseStudy; rm -rf points postProcessing
cp ../p system/pulseStudyDict; sed -i "0,/indicator   strain;/s//indicator   strian;/" system/pulseStudyDict; tryt 40 "indicator strian" pulseStudy; rm -rf points postProcessing; ls
