#!/bin/bash
# CASETIMEOUT=900
# l05 (new, class 3/5: the analysis read beside a running solver, a second terminal): bd restarted to 60e-9 in the
# background; while it runs (at about 5-6 ns simulated): tutorials/blast/plotBlast.py, bench/blast/checkLongRun.py (if
# it takes a case), incidentWindow.py and planeWave -check on the running case. Expected: each says the run is going on
# (the case in use, or its results partial) or refuses; a table or a peak printed from the unfinished logs rc 0 without a
# word = SILENT (low); a traceback from a half-written row = CRASH (low).
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 60e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 & p=$!; waitFor 120 test -d 5e-09; echo "   at the reads: times $(ls -d [0-9]* | tr '\n' ' ') | running: $([ -e /proc/$p ] && echo yes || echo no)"
py() { tryt 120 "$1" /usr/bin/python3 "${@:2}"; echo "   rc-said: $(grep -a -i -m2 'running\|in use\|partial\|not finished\|going on\|error\|Traceback' $W/try.log | tr '\n' '|' | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-160)"; }
py "(a) plotBlast.py on the running case" $ROOT/tutorials/blast/plotBlast.py .
py "(b) tests/blast/checkLongRun.py . 60e-9 on the running case" $ROOT/tests/blast/checkLongRun.py . 60e-9; py "(b2) tests/blast/checkPreview.py . 20e-6 on the running case" $ROOT/tests/blast/checkPreview.py . 20e-6; py "(b3) tests/blast/checkPreview.py (no arguments)" $ROOT/tests/blast/checkPreview.py
py "(c) incidentWindow.py on the running case" $ROOT/bench/blast/analysis/incidentWindow.py .
tryt 300 "(d) planeWave -check on the running case" planeWave -case . -check; echo "   said: $(say 2 | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -1 | cut -c1-160)"
echo "   still running after the reads: $([ -e /proc/$p ] && echo yes || echo no)"; kill $p 2>/dev/null; wait $p; echo "   run stopped (rc $?)"
