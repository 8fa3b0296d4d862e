#!/bin/bash
# w33: ind: an OLDER restart.h5 of the same run (saved at a kill at 1.5 s) put back after the run was restarted and killed again at 2 s later: restart refused (force.dat has later rows)?
. "$(dirname "$0")/../lib.sh"
indKilled 1.5; cp postProcessing/indentation/restart.h5 ../old.h5; cellIndentationFoam > log.2 2>&1 & p=$!; sleep 2; kill -KILL $p; wait $p 2>/dev/null; echo "force rows now $(grep -vc '^#' postProcessing/indentation/force.dat)"
cp ../old.h5 postProcessing/indentation/restart.h5; run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
