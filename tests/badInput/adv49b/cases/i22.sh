#!/bin/bash
# i22 (class 5, the other fields of a restart time, -acceptEdited): bd's 2e-09 with (a) T's internal field NaN in cell 5, (b) p's
# cell 5 = -1e9 (below the law's tension), (c) U's cell 5 = (1e9 0 0), (d) T every cell 0; restart to 3e-9 with -acceptEdited:
# refused naming the field and cell, or run with those fields recomputed from the conservative state (then equal to the clean
# restart); never a floating-point exception, a NaN in a log, or a silently different result.
. "$(dirname "$0")/../lib.sh"
bd; rs; cd $W; mv blast b0; cp -a b0 ref; cd ref; tryt 300 "clean restart" cellBlastFoam
one() { rm -rf $W/blast; cp -a $W/b0 $W/blast; cd $W/blast; }
one; fset 2e-09/T internal 5 nan; tryt 300 "(a) T nan" cellBlastFoam -acceptEdited; [ -d 3e-09 ] && cmpRef $W/ref
one; fset 2e-09/p internal 5 -1e9; tryt 300 "(b) p -1e9" cellBlastFoam -acceptEdited; [ -d 3e-09 ] && cmpRef $W/ref
one; fset 2e-09/U internal 5 1e9 0 0; tryt 300 "(c) U 1e9" cellBlastFoam -acceptEdited; [ -d 3e-09 ] && cmpRef $W/ref
one; fset 2e-09/T internal -1 0; tryt 300 "(d) T 0 everywhere" cellBlastFoam -acceptEdited; [ -d 3e-09 ] && cmpRef $W/ref
