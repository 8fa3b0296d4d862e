#!/bin/bash
# b28 (class 4+2, calibrateCell in a case whose path holds unicode, outputs through an existing calibrated file): the calibration tutorial in $W/célula (maxIterations 1); the user's own constant/solidProperties.calibrated (an edited earlier result) and postProcessing/calibration/results.md present: the run works or is refused naming the path; the user's files replaced as documented (outputs replaced without asking) or kept - said?
. "$(dirname "$0")/../lib.sh"
cal; cd $W; mv cal "célula"; cd "célula"; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; mkdir -p postProcessing/calibration; echo "// b28 my edited calibration" > constant/solidProperties.calibrated; echo "# b28 my results notes" > postProcessing/calibration/results.md
run 250 calibrateCell -case . -nProcs 1 > ../log.c 2>&1; grep -a -i -m3 'error\|refus\|Traceback\|Written\|converged' ../log.c | cut -c1-220; kept "b28 my edited calibration" "b28 my results notes"
