#!/bin/bash
# f11 (class 3, solidToFoam during a run): the preview restarted to 6e-9 in the background; once it runs (its lock there), solidToFoam solid/solid.h5: refused naming the run (lock), nothing written by it; the run ends rc 0 with solid.h5 and solid.xmf of 6 steps.
. "$(dirname "$0")/../lib.sh"
bd; blastEnd 6e-9 1e-9; latest; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -d 3e-09; echo "   lock: $(lk | cut -c1-80)"
tryt 60 "solidToFoam during the run" solidToFoam solid/solid.h5; ls -d constant/solid 2>/dev/null
wait $p; echo "   run rc=$?"; after; echo "   xmf steps $(xmfsteps solid/solid.xmf)"
