#!/bin/bash
# CASETIMEOUT=600
# l04 (new, class 3: two conversions at once, a second terminal): the finished preview bd continued to 6e-9 (more
# steps), then (a) two `solidToFoam solid/solid.h5` started 0.2 s apart in the same case; (b) solidToFoam while a
# restart of the case (to 8e-9) runs; (c) two `planeWave -layered -case .` at once (planeWave and -layered write
# postProcessing/planeWave/). Expected: the second refused naming the first (the case in use), the first's output whole
# (every time's solid fields present and readable); both writing constant/solid and <time>/solid at once = DATALOSS /
# SILENT if the fields are mixed.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 6e-9 1e-9; rm -f .runLock; tryt 400 "(0) bd continued to 6e-9" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | solid.h5 steps $(h5steps solid/solid.h5)"; cd $W; cp -a blast b0; cd blast
solidToFoam solid/solid.h5 > $W/s1.log 2>&1 & p1=$!; sleep 0.2; tryt 200 "(a) a second solidToFoam 0.2 s after the first" solidToFoam solid/solid.h5; wait $p1; r1=$?
echo "   first rc $r1: $(grep -a -i -m1 'error\|in use\|FATAL' $W/s1.log | cut -c1-200) | second said: $(say 2 | cut -c1-250)"
echo "   times with solid/: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' ') | constant/solid/polyMesh: $(ls constant/solid/polyMesh 2>/dev/null | tr '\n' ' ')"
cd $W; rm -rf blast; cp -a b0 blast; cd blast; latest; blastEnd 8e-9 1e-9; cellBlastFoam > $W/r.log 2>&1 & p2=$!; waitFor 60 test -s .runLock; sleep 1
tryt 200 "(b) solidToFoam while the restart to 8e-9 runs" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-250)"; wait $p2; echo "   restart rc $? End $(grep -a -c '^End' $W/r.log)"
cd $W; rm -rf blast; cp -a b0 blast; cd blast
planeWave -case . -layered > $W/pw1.log 2>&1 & p3=$!; sleep 0.5; tryt 600 "(c) a second planeWave -layered 0.5 s after the first" planeWave -case . -layered; wait $p3; r3=$?
echo "   first rc $r3: $(grep -a -i -m1 'error\|in use' $W/pw1.log | cut -c1-200) | second said: $(say 2 | cut -c1-250) | planeWave/: $(ls -R postProcessing/planeWave 2>/dev/null | tr '\n' ' ' | cut -c1-200)"
