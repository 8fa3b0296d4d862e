#!/bin/bash
# f32 (environment, a read-only temporary folder): TMPDIR pointing at a read-only folder: calibrateCell (its default -work is a new temporary folder) and sweepCase on the sod case: each an error naming the folder and that it cannot be written, rc != 0, no traceback; nothing of the case changed.
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/rotmp; ro $W/rotmp; cal; sums > ../s0
TMPDIR=$W/rotmp tryt 60 "calibrateCell, TMPDIR read-only" calibrateCell; echo "   changed: $(changed ../s0)"; grep -a -c Traceback $W/try.log; killIn $W/cal
sod; TMPDIR=$W/rotmp tryt 120 "sweepCase, TMPDIR read-only" sweepCase -entry system/controlDict/maxCo -values 0.4 -output 'p'; grep -a -c Traceback $W/try.log
