#!/bin/bash
# CASETIMEOUT=900
# l18 (new, class 4/2: the scripts' output folders with the names users give: spaces, a leading dash, a dot, a path into
# the project's own tutorials - in a copy of the project (prj), whose tutorials/ is copied): (a) tests/blast/runPreview.sh
# "$W/my runs/p 1" -noRun (spaces); (b) runPreview.sh -- -noRun? (a DIR "-d" named like an option: `runPreview.sh -d`);
# (c) runPreview.sh . -noRun in a user's folder (the current folder); (d) runPreview.sh <proj>/tutorials/blast -noRun (the
# tutorial's own parent: its sources); (e) tutorials/indentation/gapStudy.sh averageCell x with WORK inside the tutorial's folder (the case copied into itself).
# Expected: (a) runs (spaces kept) or refused naming the path; (b)-(e) refused naming what the folder holds, nothing
# removed (the tutorials' sources unchanged: git status of the copy); a source file removed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun"
prj; P=$PWD; cd $P/tutorials; find . -type f | sort | xargs md5sum > $W/t0; cd $W
tryt 400 "(a) runPreview.sh '$W/my runs/p 1'" bash $P/tests/blast/runPreview.sh "$W/my runs/p 1" $O; echo "   said: $(say 2 | cut -c1-250) | made: $(ls "$W/my runs/p 1/axisymmetricPreview" 2>/dev/null | tr '\n' ' ' | cut -c1-150)"
mkdir -p $W/u; cd $W/u; mark notes.txt; tryt 120 "(b) runPreview.sh -d (a folder named like an option)" bash $P/tests/blast/runPreview.sh -d $O; echo "   said: $(say 2 | cut -c1-250) | u: $(ls -A | tr '\n' ' ')"
tryt 120 "(c) runPreview.sh . (the user's current folder)" bash $P/tests/blast/runPreview.sh . $O; echo "   said: $(say 2 | cut -c1-250)"; kept_ notes.txt
cd $W; tryt 120 "(d) runPreview.sh <proj>/tutorials/blast (the tutorials' own folder)" bash $P/tests/blast/runPreview.sh $P/tutorials/blast $O; echo "   said: $(say 2 | cut -c1-250)"
G=$P/tutorials/indentation/gapStudy.sh; cd $W; tryt 300 "(e) WORK=<proj>/tutorials/indentation/averageCell gapStudy.sh averageCell x (WORK inside the tutorial)" env WORK=$P/tutorials/indentation/averageCell bash $G averageCell x; echo "   rc-said: $(say 2 | cut -c1-250) | last: $(tail -1 $W/try.log | cut -c1-150)"
cd $P/tutorials; find . -type f | sort | xargs md5sum > $W/t1; echo "   the copy's tutorials/: $(diff $W/t0 $W/t1 | grep -c '^<') files changed or removed, $(diff $W/t0 $W/t1 | grep -c '^>') new or changed: $(diff $W/t0 $W/t1 | grep '^[<>]' | awk '{print $1, $3}' | head -6 | tr '\n' ' ')"
