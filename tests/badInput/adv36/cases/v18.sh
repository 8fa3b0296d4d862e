#!/bin/bash
# v18: ind: peaks.dat removed after a kill, then a restart
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict ; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 3; kill -KILL $p; wait $p 2>/dev/null; wc -l postProcessing/indentation/peaks.dat; rm postProcessing/indentation/peaks.dat
cellIndentationFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8; cat postProcessing/indentation/peaks.dat 2>&1 | head -5
