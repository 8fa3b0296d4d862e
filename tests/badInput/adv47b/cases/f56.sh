#!/bin/bash
# f56 (class 3, two Allruns of the preview at once in one case): ./Allrun $PREV -noRun started twice within 0.1 s: one prepares, the other is refused naming the first (its lock), rc != 0; the prepared case is whole (.allrunOptions, constant/polyMesh, cell.msh) and a third Allrun -noRun afterwards skips or succeeds (rc 0).
. "$(dirname "$0")/../lib.sh"
prev; ./Allrun $PREV -endTime 2e-9 -noRun > ../a1 2>&1 & p1=$!; sleep 0.1; ./Allrun $PREV -endTime 2e-9 -noRun > ../a2 2>&1 & p2=$!
wait $p1; r1=$?; wait $p2; r2=$?; echo "   rc $r1 $r2"; grep -a -i -m2 'in use\|lock\|refus\|error' ../a1 ../a2 | cut -c1-220
ls constant/polyMesh constant/cell.msh .allrunOptions 2>&1 | tr '\n' ' '; echo; tryt 120 "third Allrun -noRun" ./Allrun $PREV -endTime 2e-9 -noRun
