#!/bin/bash
# CASETIMEOUT=600
# u10 (fix19i row "a script's output folder, what it holds and a run inside it" (outputFolder's "@case" entries),
# varied: a user's files inside the script's earlier case whose names match the case's patterns): tests/blast/
# runPreview.sh DIR -noRun (small options), then the user adds, in DIR/axisymmetricPreview/: logbook.txt (matches
# "log*"), 2026-12-06-notes.txt ("[0-9]*"), myFigure.png ("*.png"), results.md, postProcessing/myAnalysis.txt, README.md
# (a user's notes), constant/myMaterials; then runPreview.sh DIR -noRun again. (b) DIR holding a stale .runLock (a dead
# pid of this host) in its case: runPreview.sh DIR -noRun. (c) runPreview.sh "" -noRun (an empty DIR). Expected: (a) every
# user's file refused and kept (reliability.md: "a user's file added to the script's earlier output (also inside its case
# folder) is refused and kept"); a user's file removed = DATALOSS; (b) the stale lock named or taken over; (c) refused.
. "$(dirname "$0")/../lib.sh"
O="-h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun"
cd $W; tryt 300 "(0) runPreview.sh DIR $O" bash $ROOT/tests/blast/runPreview.sh $W/d $O; echo "   DIR/axisymmetricPreview: $(ls $W/d/axisymmetricPreview | tr '\n' ' ' | cut -c1-200)"
C=d/axisymmetricPreview; for f in logbook.txt 2026-12-06-notes.txt myFigure.png results.md postProcessing/myAnalysis.txt constant/myMaterials; do mark $C/$f; done; echo "users data $C/README.md" > $C/README.md
tryt 300 "(a) runPreview.sh DIR again, the user's files in its case" bash $ROOT/tests/blast/runPreview.sh $W/d $O; echo "   said: $(say 3 | cut -c1-350)"
for f in logbook.txt 2026-12-06-notes.txt myFigure.png results.md postProcessing/myAnalysis.txt constant/myMaterials README.md; do kept_ $C/$f; done
cd $W; rm -rf d; tryt 300 "(0b) runPreview.sh DIR $O" bash $ROOT/tests/blast/runPreview.sh $W/d $O
sleep 100 & p=$!; kill -KILL $p; wait $p 2>/dev/null; printf 'pid %s\nhost %s\nexecutable cellBlastFoam\nstarted 2026-12-06T10:00:00\ncase %s\n' $p "$(hostname)" "$W/$C" > $C/.runLock
tryt 300 "(b) runPreview.sh DIR, a stale .runLock (dead pid $p) in its case" bash $ROOT/tests/blast/runPreview.sh $W/d $O; echo "   said: $(say 3 | cut -c1-300) | $(tail -1 $W/try.log | cut -c1-150)"
mkdir -p $W/e; cd $W/e; mark notes.txt; tryt 120 "(c) runPreview.sh '' (empty DIR) in a user's folder" bash $ROOT/tests/blast/runPreview.sh "" $O; echo "   said: $(say 3 | cut -c1-300)"; kept_ notes.txt; echo "   folder now: $(ls -A | tr '\n' ' ' | cut -c1-200)"
