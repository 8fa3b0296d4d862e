#!/bin/bash
# g68 (class 4, a write interval longer than the run; then its restart) the preview's Allrun $PREV -endTime 2e-9 -writeInterval 1e-6 -noRun (valid alone: the run writes its last time only), cellBlastFoam: exit 0 with 2e-09 written (whole: marker, solid.h5 1 step, logs), then a restart to 3e-9 with the same interval: continues from 2e-09 and writes 3e-09; never a run that ends with no time written.
. "$(dirname "$0")/../lib.sh"
prev; tryt 240 "Allrun -writeInterval 1e-6 -endTime 2e-9 -noRun" ./Allrun $(echo $PREV | sed 's/-writeInterval 1e-9//') -endTime 2e-9 -writeInterval 1e-6 -noRun; tail -1 $W/try.log | cut -c1-150
tryt 240 "cellBlastFoam" cellBlastFoam; tail -1 $W/try.log | cut -c1-80; after; ls -a 2e-09 2>/dev/null | tr '\n' ' '; echo
latest; sed -i 's/^endTime .*/endTime 3e-9;/' system/controlDict.allrun; grep -a "endTime\|writeInterval" system/controlDict.allrun | tr '\n' ' '; echo; tryt 240 "restart to 3e-9" cellBlastFoam; cont; after
