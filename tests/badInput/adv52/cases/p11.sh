#!/bin/bash
# CASETIMEOUT=900
# p11 (new, class 3: two calibrations at once that share one -work folder; the run lock is the case's, the work folder
# has a marker but no lock): two copies A and B of tutorials/calibration/averageCell; `calibrateCell -case A -work $W/wk`
# in the background, and 20 s later (while A's forward runs go on in $W/wk) `calibrateCell -case B -work $W/wk`. Then
# Expected: the second refused naming the folder in use by the first (its process), A's runs untouched; the second
# emptying or writing into A's running work folder = DATALOSS (A's runs lost or mixed).
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/calibration/averageCell $W/A; cp -r $ROOT/tutorials/calibration/averageCell $W/B; cd $W
calibrateCell -case $W/A -work $W/wk > $W/A.log 2>&1 & PA=$!; sleep 20
echo "   A at 20 s: alive $([ -e /proc/$PA ] && echo yes || echo no) | wk: $(ls $W/wk 2>/dev/null | tr '\n' ' ' | cut -c1-200) | processes in wk: $(inDir $W/wk | cut -c1-200)"
tryt 120 "(a) calibrateCell -case B -work (A's running work folder)" calibrateCell -case $W/B -work $W/wk
echo "   B said: $(grep -a -m2 -i 'error\|refus\|in use' $W/try.log | tr -s ' ' | tr '\n' ' ' | cut -c1-300) | B's last lines: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-200)"
echo "   A alive after B: $([ -e /proc/$PA ] && echo yes || echo no) | wk now: $(ls $W/wk 2>/dev/null | tr '\n' ' ' | cut -c1-200)"
sleep 20; echo "   A at +20 s: alive $([ -e /proc/$PA ] && echo yes || echo no) | A's log: $(grep -a -m2 -i 'error\|refus\|cannot\|Traceback' $W/A.log | cut -c1-200)"
kill -TERM $PA 2>/dev/null; sleep 3; kill -KILL $PA 2>/dev/null; wait $PA 2>/dev/null; killAll $W/wk; killAll $W/A
echo "   A's log end: $(tail -3 $W/A.log | tr '\n' '|' | cut -c1-300)"
