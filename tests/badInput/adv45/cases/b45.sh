#!/bin/bash
# b45 (class 4, indenterProperties odd numbers): radius, tolerance, penaltyFactor, maxDepthIncrement, holdDeltaT0, holdGrowth, maxDeltaT each set to 1e308, 1e-400, -0, a hex number, 4.9e-324, 1e400: each refused before anything is written naming the file, the entry and the range; no sigFpe, no hang?
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../ip.orig
for k in radius tolerance penaltyFactor maxDepthIncrement holdDeltaT0 holdGrowth maxDeltaT; do for v in 1e308 1e-400 -0 0x1p-30 4.9e-324 1e400; do cp ../ip.orig constant/indenterProperties; sete constant/indenterProperties $k $v
  timeout -s KILL 60 cellIndentationFoam > ../log.i 2>&1; echo "$k $v: rc=$? | $(grep -a -m1 -A3 'FATAL\|sigFpe\|rror' ../log.i | grep -av '^ *$\|^-->\|From' | tr '\n' ' ' | cut -c1-200) | written: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"; rm -rf postProcessing; done; done
