#!/bin/bash
# d57 (class 4, blast controlDict.allrun time entries odd, one at a time, 40 s; writeInterval -0 corrected after the first run: it was given twice): writeInterval -0, endTime 1e-400, deltaT 0x1p-40, maxDeltaT nan, maxCo 0, writeInterval given twice (controlDict.allrun): each refused naming file, entry and range before the first step.
. "$(dirname "$0")/../lib.sh"
blast; for e in "writeInterval -0" "endTime 1e-400" "deltaT 0x1p-40" "maxDeltaT nan" "maxCo 0"; do if [ "${e%% *}" = writeInterval ]; then printf "endTime 2e-9;\n%s;\n" "$e"; else printf "endTime 2e-9;\nwriteInterval 1e-9;\n%s;\n" "$e"; fi > system/controlDict.allrun; tryt 40 "$e" cellBlastFoam; [ -d solid ] && echo "      (ran: $(ls -d [1-9]* 2>/dev/null | tr "\n" " "))"; rm -rf [1-9]* solid postProcessing; done
printf "endTime 2e-9;\nwriteInterval 1e-9;\nwriteInterval 0.5e-9;\n" > system/controlDict.allrun; tryt 40 "writeInterval twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing
