#!/bin/bash
# i48 (class 2/5, OpenFOAM's -dry-run and -dry-run-write on a finished run): bd (finished at 2e-9, startFrom startTime):
# (a) cellBlastFoam -dry-run, (b) -dry-run-write: refused as a new start over results (no -overwrite) or run without
# changing a file of the results; then with startFrom latestTime to 3e-9 (c) -dry-run, (d) -dry-run-write: the results
# unchanged (or only a new, committed time), and (e) the plain restart afterwards equals a clean restart's (cmpRef): a
# dry run never leaves a time or a log that a later restart continues from.
. "$(dirname "$0")/../lib.sh"
bd; cd $W; cp -a blast ref; cd ref; rs; cellBlastFoam > log.r 2>&1 || echo "ref failed"; cd $W/blast; sums > ../s0
tryt 120 "(a) -dry-run, startTime" cellBlastFoam -dry-run; echo "   changed: $(changed ../s0)"; after
tryt 120 "(b) -dry-run-write, startTime" cellBlastFoam -dry-run-write; echo "   changed: $(changed ../s0)"; after
rs; sums > ../s0; tryt 120 "(c) -dry-run, latestTime" cellBlastFoam -dry-run; echo "   changed: $(changed ../s0)"; after
tryt 120 "(d) -dry-run-write, latestTime" cellBlastFoam -dry-run-write; echo "   changed: $(changed ../s0)"; after
tryt 300 "(e) plain restart after them" cellBlastFoam; cont; after; cmpRef $W/ref
