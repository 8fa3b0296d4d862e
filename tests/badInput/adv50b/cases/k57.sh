#!/bin/bash
# k57 (class 4, a study's base options that the base case's Allrun does not take or that clash): the one-point study with baseOptions (-oGrid orthogonal) (an option of the quarter, not of the preview), (-h 0.25e-6 -h 0.5e-6) (given twice), (-endTime 1e-9) with duration 2e-9 (the run ends before the pulse does), (-writeInterval 3e-9) with sampleInterval 0.5e-9. Expected: refused before any point runs, naming baseOptions and the option (or the clash); no point folder left half made without a word.
. "$(dirname "$0")/../lib.sh"
study; F=system/pulseStudyDict; cp $F $W/p0
for b in "(-oGrid orthogonal)" "(-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -h 0.5e-6)" "(-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 1e-9)" "(-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -writeInterval 3e-9)"; do cp $W/p0 $F; setStudy baseOptions "$b"
  tryt 300 "baseOptions $b" pulseStudy; echo "      points: $(ls points 2>/dev/null | tr '\n' ' ') $(ls points/*/ 2>/dev/null | head -3 | tr '\n' ' ')"; rm -rf points postProcessing; done
