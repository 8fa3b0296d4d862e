#!/bin/bash
# b24 (class 2, paperFigures interrupted, then -noRun): paperFigures SIGTERMed once its averageCell run has begun; then paperFigures -noRun: an error naming the run that is not current (unfinished), nothing removed or re-made (the interrupted folder and its files as they were); then the user's note in it and paperFigures again (SIGTERMed once running): the note kept?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; R=postProcessing/runs/averageCell
setsid paperFigures > ../log.p1 2>&1 & p=$!; waitFor 120 test -f $R/log.Allrun; sleep 1; kill -TERM -- -$p; wait $p; echo "   first rc=$? (SIGTERM); $R: $(ls $R | tr '\n' ' ')"
cd $R; sums > $W/before; cd $W/paper; tryf "-noRun after the interruption" paperFigures -noRun; cd $R; nochange $W/before; cd $W/paper
echo "# b24 my note" > $R/notes.md; setsid paperFigures > ../log.p2 2>&1 & p=$!; waitFor 60 bash -c "test -f $R/log.Allrun && ! test -f $R/notes.md"; sleep 2; kill -TERM -- -$p 2>/dev/null; wait $p; echo "   second rc=$?"
grep -a -i -m4 'error\|refus\|kept\|aside\|running\|yours' ../log.p2 | cut -c1-260; where "# b24 my note"
