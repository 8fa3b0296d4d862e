#!/bin/bash
# g41 (class 4, Allrun numbers one unit in the last place outside their printed ranges) the preview's Allrun $PREV -noRun with -amplitude 1000000000.0000002 (above 1e9 by 2 ulp), -amplitude 1e9 (the edge, valid), -solidSubcycles 1000.0000000000001, -solidSubcycles 1001, -amplitude 4.9e-324, -endTime 1.7976931348623157e308, -endTime 1.7976931348623159e308: refused before any step naming the option, the value printed with the digits that show it outside (never "1e9 is outside (0, 1e9]"), and the range; the valid ones accepted.
. "$(dirname "$0")/../lib.sh"
prev
for o in "-amplitude 1000000000.0000002" "-solidSubcycles 1000.0000000000001" "-solidSubcycles 1001" "-amplitude 4.9e-324" "-endTime 1.7976931348623159e308" "-endTime 1.7976931348623157e308" "-amplitude 1e9"; do tryt 240 "$o" ./Allrun $PREV -noRun $o; echo "   prepared: $(ls -d constant/polyMesh 2>/dev/null)"; ./Allclean > /dev/null 2>&1; done
