#!/bin/bash
# a43 (class 2, paperFigures' own interrupted run folder holding the user's file; k21's root in paperFigures): a copy of tutorials/paper; paperFigures started, SIGTERMed once its averageCell run has begun in postProcessing/runs/averageCell/ (a copy of the tutorial, with its Allrun); the user saves notes.md into that folder; paperFigures again (SIGTERMed once it has started the run again): the note kept (moved aside with the copy, or refused and named), or removed with the folder?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; R=postProcessing/runs/averageCell
setsid paperFigures > ../log.p1 2>&1 & p=$!; waitFor 120 test -f $R/log.Allrun; sleep 1; kill -TERM -- -$p; wait $p; echo "   first paperFigures rc=$? (SIGTERM); $R: $(ls $R | tr '\n' ' ')"
echo "# a43 my notes on the comparison run" > $R/notes.md; sleep 1
setsid paperFigures > ../log.p2 2>&1 & p=$!; waitFor 60 bash -c "test -f $R/log.Allrun && ! test -f $R/notes.md"; sleep 2; kill -TERM -- -$p 2>/dev/null; wait $p; echo "   second paperFigures rc=$?"
grep -a -i -m5 'error\|refus\|kept\|aside\|running\|yours' ../log.p2 | cut -c1-260; echo "   postProcessing/runs: $(ls -a postProcessing/runs | tr '\n' ' ')"; where "# a43 my notes on the comparison run"
