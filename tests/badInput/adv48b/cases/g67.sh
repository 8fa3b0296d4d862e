#!/bin/bash
# g67 (class 3, Allclean while the preview's Allrun prepares the case) ./Allrun $PREV -endTime 2e-9 -noRun in the background; 3 s later ./Allclean: refused naming the Allrun (the case in use), nothing removed under it; the Allrun finishes and a second Allrun -noRun finds the case prepared.
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 -noRun > ../a1.log 2>&1 & p=$!; sleep 3; tryt 60 "Allclean during Allrun" ./Allclean; tail -2 $W/try.log | cut -c1-200; echo "   Allrun alive after: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
wait $p; echo "   Allrun rc=$? $(tail -1 ../a1.log | cut -c1-120)"; tryt 200 "second Allrun -noRun" ./Allrun $PREV -endTime 2e-9 -noRun; tail -2 $W/try.log | cut -c1-150; ls -d constant/polyMesh constant/cell.msh 2>&1 | tr '\n' ' '; echo
