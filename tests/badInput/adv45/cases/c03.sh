#!/bin/bash
# c03 (phase 2, class 2, paperFigures' earlier run folder moved aside, twice; from fix19b-fixed.md's a43 line (fc24fa0e's subject) only): a copy of tutorials/paper; paperFigures SIGTERMed once its averageCell run has begun; the user's notes.md put into postProcessing/runs/averageCell; paperFigures again, SIGTERMed once the run has begun again; a second note; a third paperFigures, SIGTERMed likewise: both notes kept (each aside folder distinct, said), nothing of the first aside replaced by the second?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; R=postProcessing/runs/averageCell
pf() { setsid paperFigures > ../log.p$1 2>&1 & local p=$!; waitFor 120 bash -c "test -f $R/log.Allrun && ! test -f $R/notes$2.md"; sleep 2; kill -TERM -- -$p 2>/dev/null; wait $p; echo "   paperFigures $1: rc=$? | $(grep -a -i -m3 'aside\|moved\|refus\|error\|kept' ../log.p$1 | cut -c1-240 | tr '\n' '|')"; }
pf 1 x; echo "# c03 note one" > $R/notes1.md; pf 2 1; echo "# c03 note two" > $R/notes2.md; pf 3 2
echo "   postProcessing/runs: $(ls -a postProcessing/runs | tr '\n' ' ')"; where "# c03 note one" "# c03 note two"
