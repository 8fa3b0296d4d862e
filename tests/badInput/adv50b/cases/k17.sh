#!/bin/bash
# k17 (class 5, checkQuarterRun.sh on runs it was not written for): (a) q: a parallel quarter finished at its endTime 2e-9, not reconstructed (the time directories only in processor0/1), (b) the preview bd (axisymmetric), (c) a folder that is not a case, (d) no argument and two arguments, (e) a case path with a space (a copy of q). Expected: each a non-zero exit with a message saying why (not reconstructed / not a quarter / not a case / usage), never exit 0 and never a Python traceback as the only word.
. "$(dirname "$0")/../lib.sh"
C=$ROOT/tests/blast/checkQuarterRun.sh
q; tryt 600 "(a) parallel quarter at 2e-9" bash $C .; tail -4 $W/try.log | cut -c1-200 | sed 's/^/   /'
bd; tryt 300 "(b) the preview" bash $C .; tail -2 $W/try.log | cut -c1-200 | sed 's/^/   /'
mkdir -p $W/empty; tryt 60 "(c) not a case" bash $C $W/empty; tail -1 $W/try.log | cut -c1-200 | sed 's/^/   /'
tryt 60 "(d1) no argument" bash $C; tail -1 $W/try.log | cut -c1-200 | sed 's/^/   /'; tryt 60 "(d2) two arguments" bash $C $W/q $W/blast; tail -1 $W/try.log | cut -c1-200 | sed 's/^/   /'
cp -a $W/q "$W/q space"; tryt 600 "(e) a path with a space" bash $C "$W/q space"; tail -3 $W/try.log | cut -c1-200 | sed 's/^/   /'
