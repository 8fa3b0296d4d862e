#!/bin/bash
# d70 (class 4, calibrationDict odd, one at a time, 40 s each): min above max; value outside [min, max]; log yes with min 0; a target peak endX (no such peak); a target value 0; parameter cytoplasm.C11 (no such entry); covariance auto2; relativeError 0; maxIterations 1e308: each refused before any forward run naming the entry and the valid range.
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../c
for e in "min     0.01;/min     30;" "value   1.67; /value   25; " "min     0.01;/min     0;" "peak endB;/peak endX;" "value 0.3e-9;/value 0;" "cytoplasm.C10/cytoplasm.C11" "covariance           auto;/covariance auto2;" "relativeError        0.05;/relativeError 0;" "maxIterations        20;/maxIterations 1e308;"; do cp ../c system/calibrationDict; sed -i "0,/$e/s//${e#*/}/" system/calibrationDict 2>/dev/null || sed -i "s/$e/" system/calibrationDict
  tryt 40 "${e#*/} ($(grep -c "${e#*/}" system/calibrationDict))" calibrateCell; [ -d postProcessing ] && echo "      (wrote: $(find postProcessing -type f | head -3 | tr "\n" " "))"; rm -rf postProcessing constant/solidProperties.calibrated; killIn $W; done; ls /tmp | grep -c calibrateCell
