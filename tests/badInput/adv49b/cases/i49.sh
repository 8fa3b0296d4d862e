#!/bin/bash
# i49 (class 3/2, -dry-run beside a live run, and the other solvers): (a) bd restarted to 9e-9 by hand (holding the lock);
# meanwhile `cellBlastFoam -dry-run` and `-dry-run-write` in the same case: refused naming the running process, nothing
# changed; the run ends exit 0. (b) rhoRiemannFoam -dry-run-write in a finished sod case (sodDone): refused over results or
# nothing changed; (c) cellIndentationFoam -dry-run in idn: refused as an invalid option (exit 1) with nothing changed.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 9e-9 1e-9; cellBlastFoam > log.run 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 0.5
tryt 60 "(a) -dry-run beside a run" cellBlastFoam -dry-run; tryt 60 "(a) -dry-run-write beside a run" cellBlastFoam -dry-run-write; wait $p; echo "   run exit $?"; after
sodDone; sums > ../s0; tryt 120 "(b) rhoRiemannFoam -dry-run-write over a finished sod" rhoRiemannFoam -dry-run-write; echo "   changed: $(changed ../s0)"
idn; sums > ../s0; tryt 60 "(c) cellIndentationFoam -dry-run" cellIndentationFoam -dry-run; echo "   changed: $(changed ../s0)"
