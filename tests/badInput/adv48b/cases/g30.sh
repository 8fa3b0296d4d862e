#!/bin/bash
# g30 (class 4, Allrun -motionDistance at its edges) the preview's Allrun $PREV -noRun with -motionDistance 0, -0, -1e-6, 4.9e-324, 1e-300, nan, inf, 1e400, 5e-6x, "" and given twice (5e-6 and 6e-6): each refused before any step, naming -motionDistance, the value and the valid range (> 0 m); nothing written (no log.*, no .allrun file).
. "$(dirname "$0")/../lib.sh"
prev
for v in 0 -0 -1e-6 4.9e-324 1e-300 nan inf 1e400 5e-6x ""; do tryt 120 "-motionDistance '$v'" ./Allrun $PREV -endTime 2e-9 -noRun -motionDistance "$v"; echo "   written: $(ls -d log.* *.allrun constant/*.allrun system/*.allrun .allrunOptions 2>/dev/null | tr '\n' ' ')"; ./Allclean > /dev/null 2>&1; done
tryt 120 "-motionDistance given twice" ./Allrun $PREV -endTime 2e-9 -noRun -motionDistance 5e-6 -motionDistance 6e-6; echo "   written: $(ls -d log.* constant/*.allrun 2>/dev/null | tr '\n' ' ')"; grep -a motionDistance constant/fsiProperties.allrun 2>/dev/null
