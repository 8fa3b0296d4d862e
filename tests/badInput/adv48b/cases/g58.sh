#!/bin/bash
# g58 (class 3, cellMesh on a case that is running) bd restarted to 3e-9 in the background; during it cellMesh (which would replace constant/cell.msh under the run): refused naming the run; constant/cell.msh unchanged; the run finishes.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; md5sum constant/*.msh > ../m0; cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -s .runLock; sleep 2; tryt 120 "cellMesh during the run" cellMesh; md5sum -c ../m0 2>&1 | tr '\n' ' '; echo; wait $p; echo "   run rc=$?"; after
