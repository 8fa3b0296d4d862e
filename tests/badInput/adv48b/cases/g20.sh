#!/bin/bash
# g20 (class 1, an older checkpoint of the same run put back) ik: restart.h5 copied, the run continued ~4 s and SIGKILLed again (force.dat, solid.h5 and restart.h5 further), the older restart.h5 put back, restart to the end: refused naming restart.h5 (older than force.dat/solid.h5), or every file cut back to it and continued so that force.dat equals B's (ik restarted untouched to the end) with times increasing; never rows twice.
. "$(dirname "$0")/../lib.sh"
ik; mv $W/ind $W/B; cd $W/B; tryt 400 "B restart" cellIndentationFoam
ik; cp postProcessing/indentation/restart.h5 ../old.h5; echo "   rows at the copy: $(nLines postProcessing/indentation/force.dat)"
cellIndentationFoam > ../run2.log 2>&1 & p=$!; sleep 4; i=0; until ! cmp -s postProcessing/indentation/restart.h5 ../old.h5 || [ $i -ge 100 ]; do sleep 0.5; i=$((i+1)); done; sleep 1; kill -KILL $p; wait $p 2>/dev/null; rm -f .runLock
echo "   after the second kill: rows $(nLines postProcessing/indentation/force.dat), restart.h5 $(cmp -s postProcessing/indentation/restart.h5 ../old.h5 && echo unchanged || echo newer)"
cp ../old.h5 postProcessing/indentation/restart.h5; sums > ../s0
tryt 400 "older restart.h5 put back" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after; f=postProcessing/indentation/force.dat; forceOk $f; cmp -s $f $W/B/$f && echo "   force.dat same as B" || echo "   force.dat DIFF from B ($(nLines $f) rows here, $(nLines $W/B/$f) in B)"
