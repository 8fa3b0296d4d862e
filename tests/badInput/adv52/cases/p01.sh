#!/bin/bash
# CASETIMEOUT=900
# p01 (new, class 3/2: two runs of a script's output folder at once; etc/scratchFolder has no lock): tests/blast/
# runPreview.sh DIR -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 4e-9 -writeInterval 1e-9 -noPlots (the first,
# in the background), and 15 s later, while its Allrun meshes or its solver runs, (a) a second runPreview.sh DIR -noRun
# with the same DIR. Then (b) bench/restart/restartDigits.sh OUT 17 twice, the second 8 s after the first. Expected: the
# second refused naming the running one (the folder in use), the first's case and run whole (rc 0); the second emptying
# the folder under the first's running solver = DATALOSS.
. "$(dirname "$0")/../lib.sh"
D=$W/d; cd $W
bash $ROOT/tests/blast/runPreview.sh $D -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -endTime 4e-9 -writeInterval 1e-9 -noPlots -noVTK > $W/first.log 2>&1 & P1=$!
sleep 15; echo "   at 15 s the first is in: $(ls $D/axisymmetricPreview 2>/dev/null | tr '\n' ' ' | cut -c1-200) | lock: $(head -c 100 $D/axisymmetricPreview/.runLock 2>/dev/null | tr '\n' ' ')"
echo "   processes in DIR: $(inDir $D | cut -c1-250)"
tryt 120 "(a) a second runPreview.sh DIR -noRun while the first runs" bash $ROOT/tests/blast/runPreview.sh $D -h 0.25e-6 -far 2e-6 -cell 0.5e-6 -Z 20e-6 -noRun -noPlots -noVTK
echo "   second said: $(grep -a -m3 -i 'error\|refus\|in use\|exists' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-400)"
wait $P1; echo "   first rc $? | its log: $(tail -3 $W/first.log | tr '\n' '|' | cut -c1-300)"; echo "   first's case now: $(ls $D/axisymmetricPreview 2>/dev/null | tr '\n' ' ' | cut -c1-250)"
echo "   times: $(cd $D/axisymmetricPreview 2>/dev/null && ls -d [0-9]* | tr '\n' ' ') | solver End: $(grep -a -c '^End' $D/axisymmetricPreview/log.cellBlastFoam 2>/dev/null)"
O=$W/o; bash $ROOT/bench/restart/restartDigits.sh $O 17 > $W/rd1.log 2>&1 & P2=$!; sleep 8; echo "   restartDigits first at 8 s: $(ls -R $O 2>/dev/null | head -20 | tr '\n' ' ' | cut -c1-200)"
tryt 300 "(b) a second restartDigits.sh OUT 17 while the first runs" bash $ROOT/bench/restart/restartDigits.sh $O 17
echo "   second said: $(grep -a -m3 -i 'error\|refus\|in use\|exists' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300) | second's table: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-200)"
wait $P2; echo "   first rc $? | its log: $(grep -a -v '^ *$' $W/rd1.log | tail -3 | tr '\n' '|' | cut -c1-400)"
