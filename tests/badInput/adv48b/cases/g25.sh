#!/bin/bash
# g25 (class 2/environment, a read-only tutorial folder) a copy of the preview made read-only (bind mount), ./Allrun $PREV -noRun: refused at once, exit non-zero, naming the folder as not writable; no traceback, no partial state (nothing could be written); then ./Allclean there: refused or nothing, exit non-zero with a message.
. "$(dirname "$0")/../lib.sh"
prev; ro $W/c; tryt 120 "Allrun -noRun, read-only case" ./Allrun $PREV -endTime 2e-9 -noRun; tail -3 $W/try.log | cut -c1-200
tryt 60 "Allclean, read-only case" ./Allclean; tail -2 $W/try.log | cut -c1-200
