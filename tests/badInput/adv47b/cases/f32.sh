#!/bin/bash
# f32 (environment, a read-only temporary folder): TMPDIR pointing at a read-only folder: calibrateCell (its default -work is "a new temporary one"), planeWave on the finished preview (its 1D column's scratch folder) and sweepCase on the sod case: each either works elsewhere (rc 0 / runs) or stops with an error naming the folder and that it cannot be written, rc != 0, no traceback; nothing of the case changed by a failure.
# (corrected after its first run: the first version judged calibrateCell from sweepCase's log and gave sweepCase a wrong -output)
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/rotmp; ro $W/rotmp; touch $W/rotmp/x 2>/dev/null && echo "   (rotmp writable!)"; cal; sums > ../s0
TMPDIR=$W/rotmp tryt 60 "(a) calibrateCell, TMPDIR read-only" calibrateCell; echo "   changed: $(changed ../s0)"; grep -a -c Traceback $W/try.log; head -3 $W/try.log | cut -c1-200; killIn $W/cal
bd; TMPDIR=$W/rotmp tryt 120 "(b) planeWave, TMPDIR read-only" planeWave; grep -a -c Traceback $W/try.log; tail -2 $W/try.log | cut -c1-200
sod; TMPDIR=$W/rotmp tryt 120 "(c) sweepCase, TMPDIR read-only" sweepCase -entry system/controlDict/maxCo -values "0.4 0.45" -run rhoRiemannFoam -output "t=0.007/uniform/time:/value +([0-9.e+-]+);/"; grep -a -c Traceback $W/try.log; tail -4 $W/try.log | cut -c1-200
