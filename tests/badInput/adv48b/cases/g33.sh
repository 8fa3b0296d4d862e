#!/bin/bash
# g33 (class 4, a pulse no step can see, a pulse longer than the run) the preview's Allrun $PREV -noRun (a) -pulse 1e-20 (valid alone, shorter than any time step: the load would never be applied), (b) -pulse 1e-6 -endTime 2e-9 (longer than the run: valid), (c) -pulse 0, (d) -pulse 4.9e-324: (a) and (d) refused naming -pulse and the least duration a step resolves, or said; (b) accepted; (c) refused with the range.
. "$(dirname "$0")/../lib.sh"
prev
for o in "-pulse 0" "-pulse 4.9e-324" "-pulse 1e-20" "-pulse 1e-6"; do tryt 240 "$o" ./Allrun $PREV -endTime 2e-9 -noRun $o; grep -a -i -m2 'pulse\|warn' $W/try.log | cut -c1-200; echo "   prepared: $(ls -d constant/polyMesh 2>/dev/null)"; grep -a -A4 -i 'table\|uniformValue' 0/p 2>/dev/null | grep -a '(' | head -3 | tr '\n' ' '; echo; ./Allclean > /dev/null 2>&1; done
