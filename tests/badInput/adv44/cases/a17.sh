#!/bin/bash
# a17 (class 2, calibrateCell's outputs through SYMBOLIC LINKS): the calibration tutorial (maxIterations 1) with constant/solidProperties.calibrated a link to the user's shared material file OUTSIDE the case ($W/shared/myMaterials, "a17 my shared materials") and postProcessing/calibration/results.md a link to $W/shared/report.md; calibrateCell: the links replaced by its outputs (the shared files kept), refused, or the shared files outside the case written over?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/shared; echo "// a17 my shared materials" > $W/shared/myMaterials; echo "# a17 my shared report" > $W/shared/report.md
cal; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; mkdir -p postProcessing/calibration; ln -s $W/shared/myMaterials constant/solidProperties.calibrated; ln -s $W/shared/report.md postProcessing/calibration/results.md
run 200 calibrateCell -case . -nProcs 1 > log.1 2>&1; grep -a -i -m3 'error\|refus\|link\|Written' log.1 | cut -c1-220
echo "   links now: $(find constant postProcessing -type l | tr '\n' ' ')"; where "a17 my shared materials" "a17 my shared report"; echo "   shared/: $(head -c 60 $W/shared/myMaterials | tr '\n' ' ')"
