#!/bin/bash
# d74 (class 5+1, an older checkpoint of the same run put back: a smoke indentation with 0.01 um steps, restart.h5 copied at its first checkpoint, the run SIGKILLed after a later one, the old restart.h5 put back, restart latestTime): refused naming restart.h5 against force.dat/solid.h5 (they hold more), or continues from the older checkpoint cutting force.dat, peaks.dat and solid.h5 to it (times increasing, no row twice); SILENT if rows after the old checkpoint stay and are followed by a second copy.
. "$(dirname "$0")/../lib.sh"
ind; sed -i "s/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/" constant/indenterProperties; r=postProcessing/indentation/restart.h5
cellIndentationFoam > ../l1 2>&1 & p=$!; waitFor 120 test -f $r; cp $r ../r0; m0=$(md5sum < $r); i=0; while [ "$(md5sum < $r 2>/dev/null)" = "$m0" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i+1)); done; sleep 0.5; kill -KILL $p; wait $p 2>/dev/null
echo "   at the kill: $(forceOk postProcessing/indentation/force.dat); restart.h5 changed: $([ "$(md5sum < $r)" != "$m0" ] && echo yes || echo no)"; cp ../r0 $r; latest
tryt 200 "restart from the older checkpoint" cellIndentationFoam; cont; after; forceOk postProcessing/indentation/force.dat; forceOk postProcessing/indentation/peaks.dat; echo "   solid.h5 $(h5steps postProcessing/indentation/solid.h5) steps, xmf $(xmfsteps postProcessing/indentation/solid.xmf)"
