#!/bin/bash
# a12 (class 2, paperFigures' run folders): a copy of tutorials/paper; the user's own folder postProcessing/runs/averageCell/ (notes.md, myAnalysis/fit.py; no run of ours in it); paperFigures (nothing current: it makes the averageCell run there), SIGTERMed once it has started that run: the user's folder refused (named, kept), or removed to make the run's copy?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/paper" $W/paper; cd $W/paper; R=postProcessing/runs/averageCell; mkdir -p $R/myAnalysis; echo "# a12 my notes" > $R/notes.md; echo "# a12 my fit script" > $R/myAnalysis/fit.py
setsid paperFigures > ../log.p1 2>&1 & p=$!; waitFor 120 test -f $R/log.Allrun; echo "   the run started: $(test -f $R/log.Allrun && echo yes || echo no)"; sleep 1; kill -TERM -- -$p; wait $p; echo "   paperFigures rc=$? after SIGTERM"
grep -a -i -m6 'error\|refus\|running\|not current\|kept\|yours' ../log.p1 | cut -c1-240; echo "   $R: $(ls -a $R 2>/dev/null | tr '\n' ' ')"; where "# a12 my notes" "# a12 my fit script"
