#!/bin/bash
# CASETIMEOUT=300
# p34 (new, class 6: the size of incidentWindow.py's --series, never bounded): the finished preview with planeWave's
# reference (pwd0): --series T0 T1 DT [ns] with (a) 0 1e6 1e-6 (1e12 rows), (b) 0 100 1e-6 (1e8 rows; 30 s KILL limit,
# output to a file, its rows counted), (c) 0 2 1e-300. Expected: refused above a row limit naming --series and the count
# (as planeWave's -maxCells, sweepCase's -maxRuns); a MemoryError traceback = CRASH (low), a run of hours printing
# 1e8 rows = unbounded (class 6).
. "$(dirname "$0")/../lib.sh"
pwd0; C=$PWD; IW="$ROOT/bench/blast/analysis/incidentWindow.py"
tryt 60 "(a) --series 0 1e6 1e-6" /usr/bin/python3 $IW $C --series 0 1e6 1e-6; echo "   traceback: $(grep -a -c Traceback $W/try.log) | last: $(tail -1 $W/try.log | cut -c1-200)"
tryt 30 "(b) --series 0 100 1e-6 (30 s)" bash -c "/usr/bin/python3 $IW $C --series 0 100 1e-6 > $W/b.out 2>&1"; echo "   rows printed in 30 s: $(wc -l < $W/b.out) | distinct: $(sort -u $W/b.out | wc -l)"; rm -f $W/b.out
tryt 60 "(c) --series 0 2 1e-300" /usr/bin/python3 $IW $C --series 0 2 1e-300; echo "   traceback: $(grep -a -c Traceback $W/try.log) | last: $(tail -1 $W/try.log | cut -c1-200)"
