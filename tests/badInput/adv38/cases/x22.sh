#!/bin/bash
# x22: a keyword given once plain and once QUOTED (a quoted keyword is a regular expression in OpenFOAM): fsiProperties coupling { maxIter 30; "maxIter" 5; }, solidProperties explicitSafety and "explicitSafety", controlDict endTime and "endTime": refused as duplicates, or one silently used?
. "$(dirname "$0")/../lib.sh"
blast
sed -i 's/^\(\s*maxIter .*\)/\1\n    "maxIter"       5;/' constant/fsiProperties; try "fsi maxIter + \"maxIter\"" cellBlastFoam; grep -a -i "maxIter\|sub-iter" log.* 2>/dev/null | head -2; rm -rf [1-9]* solid postProcessing; cp $ADV/blastBase/axisymmetricPreview/constant/fsiProperties constant/
grep -n "explicitSafety" constant/solidProperties | head -2; sed -i '0,/^\(\s*\)explicitSafety\(.*\)/s//&\n"explicitSafety" 0.1;/' constant/solidProperties; grep -n "explicitSafety" constant/solidProperties | head -3; try "solid explicitSafety + quoted" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $ADV/blastBase/axisymmetricPreview/constant/solidProperties constant/
echo '"endTime" 1e-9;' >> system/controlDict; try "controlDict endTime + quoted" cellBlastFoam; echo "times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
