#!/bin/bash
# w33: ind: an OLDER restart.h5 of the same run (saved at a first kill) put back after the run was restarted and killed again later, restart to the end: refused, or continued and equal to an uninterrupted run (force.dat, peaks.dat)?
. "$(dirname "$0")/../lib.sh"
indKilled 0.5; cp -r . ../ref; (cd ../ref && rm -rf postProcessing && sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict && cellIndentationFoam > log.ref 2>&1; echo "reference rc=$?")
cp postProcessing/indentation/restart.h5 ../old.h5; cellIndentationFoam > log.2 2>&1 & p=$!; sleep 3; kill -KILL $p; wait $p 2>/dev/null; echo "force rows after the second kill $(grep -vc '^#' postProcessing/indentation/force.dat)"
cp ../old.h5 postProcessing/indentation/restart.h5; run 200 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
for f in force.dat peaks.dat; do cmp postProcessing/indentation/$f ../ref/postProcessing/indentation/$f && echo "$f equal to the uninterrupted run"; done
