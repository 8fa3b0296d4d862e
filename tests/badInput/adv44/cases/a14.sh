#!/bin/bash
# a14 (class 2, sweepCase's run folders): a two-value sweep of the smoke indentation (maxDepthIncrement 0.1e-6 0.05e-6, one at a time); while the first value runs the user saves notes into its run folder <case>.sweep_maxDepthIncrement_0/ (to look at a result); at the end (no -keep): the note removed with the run folder, named, or kept?
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6 0.05e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:1" > ../log.sw 2>&1 & p=$!
waitFor 60 test -d $W/ind.sweep_maxDepthIncrement_0/postProcessing; echo "a14 my notes on value 0" > $W/ind.sweep_maxDepthIncrement_0/notes.txt; wait $p; echo "   sweep rc=$?"; grep -a -i -m3 'error\|note\|kept\|Written' ../log.sw | cut -c1-240
echo "   left: $(ls -d $W/ind.* 2>/dev/null | tr '\n' ' ')"; where "a14 my notes on value 0"
