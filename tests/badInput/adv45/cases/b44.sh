#!/bin/bash
# b44 (class 4, the blast's controlDict odd numbers): writeInterval, endTime, deltaT, maxDeltaT, maxCo each set to 1e308, 1e-400, -0, a hex number, 4.9e-324, 1e400 (where the case sets it: controlDict.allrun, else controlDict): each refused before anything is written naming the file, the entry and the range; no sigFpe, no hang?
. "$(dirname "$0")/../lib.sh"
blast; cp system/controlDict ../cd.orig; cp system/controlDict.allrun ../cda.orig
for k in writeInterval endTime deltaT maxDeltaT maxCo; do for v in 1e308 1e-400 -0 0x1p-30 4.9e-324 1e400; do cp ../cd.orig system/controlDict; cp ../cda.orig system/controlDict.allrun
  if grep -q "^$k " system/controlDict.allrun; then sete system/controlDict.allrun $k $v; else sete system/controlDict $k $v; fi
  timeout -s KILL 60 cellBlastFoam > ../log.b 2>&1; echo "$k $v: rc=$? | $(grep -a -m1 -A3 'FATAL\|sigFpe\|rror' ../log.b | grep -av '^ *$\|^-->\|From' | tr '\n' ' ' | cut -c1-200) | written: $(ls -d [1-9]* solid 2>/dev/null | tr '\n' ' ')"; rm -rf [1-9]* solid postProcessing; done; done
