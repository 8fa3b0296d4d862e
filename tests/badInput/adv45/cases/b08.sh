#!/bin/bash
# b08 (class 2, sweepCase over a FINISHED case): the smoke indentation run to its end (force.dat, peaks.dat, solid.h5, restart.h5 in the case); sweepCase -values "0.1e-6 0.05e-6" (maxDepthIncrement): each copy carries the earlier results: the runs refused (a new start over results) and the sweep says why, or the copies start clean; never a table of the old results; the case's results unchanged?
. "$(dirname "$0")/../lib.sh"
indDone; sums > ../before
tryf "sweep a finished case" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
nochange ../before; echo "   left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename | tr '\n' ' ')"
