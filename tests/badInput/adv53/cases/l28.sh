#!/bin/bash
# CASETIMEOUT=900
# l28 (new, class 3/2: fix19i's documented window - "a second script started before the first's solver took its lock
# (while it copies or meshes) still empties the folder" - with another script and a shell loop): (a) two
# tutorials/indentation/gapStudy.sh averageCell base with the same WORK, the second 1 s after the first (the first is
# copying or meshing); (b) tests/blast/runPreview.sh D (to 4e-9) and, 1 s later, runPreview.sh D -noRun. Expected: the
# second refused naming the first (the folder in use), the first's run whole (rc 0, its table); the second emptying the
# first's folder = DATALOSS.
. "$(dirname "$0")/../lib.sh"
cd $W; env WORK=$W/g bash $ROOT/tutorials/indentation/gapStudy.sh averageCell base > $W/g1.log 2>&1 & p1=$!; sleep 1; echo "   the first at 1 s: $(ls $W/g/averageCell_base 2>/dev/null | tr '\n' ' ' | cut -c1-150)"
tryt 600 "(a) a second gapStudy.sh averageCell base (same WORK) 1 s after the first" env WORK=$W/g bash $ROOT/tutorials/indentation/gapStudy.sh averageCell base; echo "   second said: $(say 2 | cut -c1-250) | last: $(tail -1 $W/try.log | cut -c1-150)"
wait $p1; echo "   first rc $? | its last lines: $(tail -2 $W/g1.log | tr '\n' '|' | cut -c1-250)"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -noPlots -noVTK"
bash $ROOT/tests/blast/runPreview.sh $W/D $O -endTime 4e-9 > $W/r1.log 2>&1 & p2=$!; sleep 1; echo "   the first at 1 s: $(ls $W/D/axisymmetricPreview 2>/dev/null | tr '\n' ' ' | cut -c1-150)"
tryt 300 "(b) a second runPreview.sh D -noRun 1 s after the first" bash $ROOT/tests/blast/runPreview.sh $W/D $O -noRun; echo "   second said: $(say 2 | cut -c1-250)"
wait $p2; echo "   first rc $? | its last lines: $(tail -2 $W/r1.log | tr '\n' '|' | cut -c1-250) | times: $(ls -d $W/D/axisymmetricPreview/[0-9]* 2>/dev/null | xargs -n1 basename 2>/dev/null | tr '\n' ' ')"
