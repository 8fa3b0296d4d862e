#!/bin/bash
# k15 (class 2, calibrateCell's outputs): the user's notes.md in postProcessing/calibration/ and an edited constant/solidProperties.calibrated of an earlier fit (the user's "k15 my edited calibration") BEFORE calibrateCell (maxIterations 1, -nProcs 1); then the user's notes in -work's folder before a second run with -work: kept, refused, or written over without a word?
. "$(dirname "$0")/../lib.sh"
cal; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; mkdir -p postProcessing/calibration; echo "# k15 cal notes" > postProcessing/calibration/notes.md
cp constant/solidProperties constant/solidProperties.calibrated; echo "// k15 my edited calibration" >> constant/solidProperties.calibrated
run 200 calibrateCell -case . -nProcs 1 > log.1 2>&1; grep -a -i -m3 'error\|refus\|exists\|overwrite\|calibrated' log.1 | cut -c1-220; echo "   postProcessing/calibration: $(ls postProcessing/calibration | tr '\n' ' ')"; kept "k15 cal notes" "k15 my edited calibration"
mkdir -p ../cw; echo "k15 work notes" > ../cw/notes.txt; run 200 calibrateCell -case . -nProcs 1 -work ../cw > log.2 2>&1; grep -a -i -m3 'error\|refus\|exists\|did not write' log.2 | cut -c1-220; kept "k15 cal notes"; echo "   ../cw: $(ls ../cw 2>/dev/null | tr '\n' ' '); $(grep -l 'k15 work notes' ../cw/notes.txt 2>/dev/null || echo 'k15 work notes GONE')"
