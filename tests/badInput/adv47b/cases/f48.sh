#!/bin/bash
# f48 (class 4, the preview Allrun's option ranges at their edges, -noRun): -amplitude 1e9 (the bound: accepted, preparation starts), 1.0000000000000002e9 (refused naming -amplitude and (0, 1e9]), 4.9e-324 (refused: below the reader), -solidSubcycles 1e3 (1000: accepted or refused as not written whole - either said), 1000.0000000000001 (refused), -endTime -0 (refused). Accepted ones are stopped after 25 s and the copy cleaned.
. "$(dirname "$0")/../lib.sh"
prev; for o in "-amplitude 1e9" "-amplitude 1.0000000000000002e9" "-amplitude 4.9e-324" "-solidSubcycles 1e3" "-solidSubcycles 1000.0000000000001" "-endTime -0"; do
  tryt 25 "$o" ./Allrun $PREV -noRun $o; [ -f .allrunOptions ] && echo "   (accepted: .allrunOptions written)"; killIn $W/c; ./Allclean > /dev/null 2>&1; done
