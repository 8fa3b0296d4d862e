#!/bin/bash
# b25 (class 4, calibrationDict odd numbers): tolerance, finiteDifferenceStep, meshSizeFactor, relativeError, maxIterations, nProcs, a parameter's value/min/max, a target's value, each set to 1e308, 1e-400, -0, a hex number, 4.9e-324, 1e400: each refused before any forward run naming the file, the entry and the range; no traceback; nothing written?
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../dict.orig
for k in tolerance finiteDifferenceStep meshSizeFactor relativeError maxIterations nProcs value min F_B; do for v in 1e308 1e-400 -0 0x1p-10 4.9e-324 1e400; do cp ../dict.orig system/calibrationDict
  case $k in value|min) sed -i "0,/^\( *\)$k .*/s//\1$k $v;/" system/calibrationDict;; F_B) sed -i "s/F_B { peak endB; value 0.3e-9; }/F_B { peak endB; value $v; }/" system/calibrationDict;; *) sete system/calibrationDict $k $v;; esac
  timeout -s KILL 60 calibrateCell -case . > ../log.c 2>&1; echo "$k $v: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|evaluation' ../log.c | cut -c1-200)"; done; done; echo "   written: $(ls -a postProcessing constant 2>/dev/null | grep -i calib | tr '\n' ' ')"
