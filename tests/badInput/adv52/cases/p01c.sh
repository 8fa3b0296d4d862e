#!/bin/bash
# CASETIMEOUT=900
# p01c (p01b at other moments: fix19i's fc180866 says "the window before the first's solver takes its lock remains"):
# tests/blast/runPreview.sh DIR ... -endTime 1e-8 (the first, in the background) and a second `runPreview.sh DIR ...
# -noRun` with the same DIR (a) 0.3 s, (b) 2 s, (c) 6 s after it (while the first copies the tutorial, meshes, or its
# solver starts). Expected: the second refused naming the first (in use), the first's run whole (rc 0, End); the first
# failing because its folder was emptied = DATALOSS.
. "$(dirname "$0")/../lib.sh"
one() { local D=$W/d$1; cd $W; bash $ROOT/tests/blast/runPreview.sh $D -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 1e-8 -writeInterval 1e-9 -noPlots -noVTK > $W/first$1.log 2>&1 & local P1=$!; sleep $1
  echo "   at $1 s: first alive $([ -e /proc/$P1 ] && echo yes || echo no) | DIR: $(ls -a $D 2>/dev/null | tr '\n' ' ' | cut -c1-100) | case: $(ls $D/axisymmetricPreview 2>/dev/null | tr '\n' ' ' | cut -c1-150)"
  tryt 120 "($2) a second runPreview.sh DIR -noRun $1 s after the first" bash $ROOT/tests/blast/runPreview.sh $D -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -noRun -noPlots -noVTK
  echo "   second said: $(grep -a -m2 -i 'error\|refus\|in use' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300)"
  wait $P1; echo "   first rc $? | its last lines: $(tail -2 $W/first$1.log | tr '\n' '|' | cut -c1-250) | End: $(grep -a -c '^End' $D/axisymmetricPreview/log.cellBlastFoam 2>/dev/null) | times: $(cd $D/axisymmetricPreview 2>/dev/null && ls -d [0-9]* | tr '\n' ' ')"; }
one 0.3 a; one 2 b; one 6 c
