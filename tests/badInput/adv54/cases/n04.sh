#!/bin/bash
# CASETIMEOUT=300
# n04 (new, class 5: digested results cut at a line boundary): the finished smoke indentation (idn): (a) force.dat's last 3
# rows removed (`head -n -3`, the sidecar intact); (b) force.dat and its sidecar both cut by 3 lines (as a run killed 3
# rows before its end would leave them, but the run had finished: restart.h5 and peaks.dat say so); (c) peaks.dat and
# its sidecar both cut to their first 2 rows (endB and C1,i left); plotIndentation.py each. Expected: (a) refused naming
# the cut; (b), (c) refused or said "the run is not finished / rows missing" (its results then are not the run's); a
# table of the cut rows without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
idn; cp -a . $W/i0; d=postProcessing/indentation
head -n -3 $d/force.dat > $W/x; cat $W/x > $d/force.dat; pi; echo "   (a) $(pk)"
cd $W; rm -rf ind; cp -a i0 ind; cd ind; for f in force.dat force.dat.fnv1a64; do head -n -3 $d/$f > $W/x; cat $W/x > $d/$f; done; pi; echo "   (b) $(pk) | force rows $(grep -vc '^#' $d/force.dat)"; ok_ $d/force.dat
cd $W; rm -rf ind; cp -a i0 ind; cd ind; head -n 4 $d/peaks.dat > $W/x; cat $W/x > $d/peaks.dat; head -n 2 $d/peaks.dat.fnv1a64 > $W/x; cat $W/x > $d/peaks.dat.fnv1a64; pi; echo "   (c) $(pk)"; grep -a 'nan\|C2' $W/try.log | head -2
