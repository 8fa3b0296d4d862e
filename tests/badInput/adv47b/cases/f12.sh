#!/bin/bash
# f12 (class 3, foamToVTK during a run): the preview restarted to 6e-9 in the background, OpenFOAM's foamToVTK run beside it twice (documented: the user's part); the run must end rc 0 untouched, and a restart after it to 7e-9 continue (nothing of the run's state broken): both rc 0.
. "$(dirname "$0")/../lib.sh"
bd; blastEnd 6e-9 1e-9; latest; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -d 3e-09
tryt 60 "foamToVTK during the run (1)" foamToVTK; tryt 60 "foamToVTK during the run (2)" foamToVTK -latestTime
wait $p; echo "   run rc=$?"; after
blastEnd 7e-9 1e-9; tryt 240 "restart after" cellBlastFoam; cont; after
