#!/bin/bash
# CASETIMEOUT=900
# h15 (class 4, h09's rest: h09 was cut by its 900 s timeout at pulseStudy's last value (each pulseStudy start took ~30 s
# at load 23)): pulseStudy sampleInterval 1e-310 (maxPoints 1 appended), and calibrateCell's relativeError given
# -DBL_MAX, DBL_MAX, 1e308, -1e308, 1e309, inf, -inf, nan, -0, 4.9e-324, 1e-310: each refused (rc != 0, no Traceback)
# naming the entry, the file and the valid range, or accepted if in range (cut at 30 s). One line each.
. "$(dirname "$0")/../lib.sh"
V="-1.7976931348623157e308 1.7976931348623157e308 1e308 -1e308 1e309 inf -inf nan -0 4.9e-324 1e-310"
show() { local rc=$1; echo "   [$2] rc=$rc traceback=$(grep -a -c Traceback $W/try.log) | $(grep -a -m1 -A2 'FATAL\|[Ee]rror\|refused\|outside\|not a\|invalid\|must' $W/try.log | grep -av '^ *$\|^-->\|From function' | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-330)"; }
study; echo "maxPoints 1;" >> system/pulseStudyDict; sete system/pulseStudyDict sampleInterval 1e-310; timeout -s KILL 60 pulseStudy > $W/try.log 2>&1; show $? "pulseStudy sampleInterval 1e-310"; killIn $W
cd $W; cal; cp system/calibrationDict ../cd; echo "== calibrateCell relativeError"
for v in $V; do cp ../cd system/calibrationDict; sete system/calibrationDict relativeError $v; timeout -s KILL 30 calibrateCell > $W/try.log 2>&1; show $? $v; killIn $W; rm -rf postProcessing constant/solidProperties.calibrated; done
