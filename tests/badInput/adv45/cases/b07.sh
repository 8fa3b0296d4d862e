#!/bin/bash
# b07 (class 2, sweepCase SIGKILLed, then again): a two-value sweep (-nProcs 1) SIGKILLed (the whole group) while value 0 runs; the same command again: refused naming what is left (run folder, base copy) and the way out, nothing removed; after the advice is followed, a third sweep completes?
. "$(dirname "$0")/../lib.sh"
ind
setsid sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.05e-6 0.02e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.s1 2>&1 & p=$!
waitFor 60 test -f $W/ind.sweep_maxDepthIncrement_0/postProcessing/indentation/force.dat; sleep 1; kill -KILL -- -$p; wait $p 2>/dev/null; echo "   SIGKILLed; left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename | tr '\n' ' ')"; echo "user note" > $W/ind.sweep_maxDepthIncrement_0/note.txt
tryf "again" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.05e-6 0.02e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; echo "   left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename | tr '\n' ' ')"; where "user note"
grep -a -i -o 'remove[^.]*\.\|move[^.]*\.' $W/try.log | head -2 | cut -c1-200; mkdir -p $W/aside; mv $W/ind.sweep_* $W/aside/ 2>/dev/null
tryf "third (leftovers moved away)" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "0.05e-6 0.02e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
