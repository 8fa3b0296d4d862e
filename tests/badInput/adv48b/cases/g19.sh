#!/bin/bash
# g19 (class 1/5, force.dat shorter than the checkpoint) ik (the killed smoke indentation) with the last 3 rows of postProcessing/indentation/force.dat removed (the checkpoint restart.h5 reaches beyond them), restart: refused naming force.dat (it ends before the checkpoint), or force.dat at the end equal to B's (ik restarted untouched); never a gap of rows.
. "$(dirname "$0")/../lib.sh"
ik; mv $W/ind $W/B; cd $W/B; tryt 400 "B restart" cellIndentationFoam; forceOk postProcessing/indentation/force.dat
ik; f=postProcessing/indentation/force.dat; echo "   force.dat rows $(nLines $f)"; head -n -3 $f > ../f && cat ../f > $f; echo "   cut to $(nLines $f)"; sums > ../s0
tryt 400 "force.dat cut by 3 rows" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after; forceOk $f; cmp -s $f $W/B/$f && echo "   force.dat same as B" || echo "   force.dat DIFF from B ($(nLines $f) rows here, $(nLines $W/B/$f) in B)"
