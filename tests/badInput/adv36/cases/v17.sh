#!/bin/bash
# v17: ind: force.dat emptied (0 bytes) after a kill, then a restart
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict ; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 2.5; kill -KILL $p; wait $p 2>/dev/null; : > postProcessing/indentation/force.dat
cellIndentationFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8; wc -l postProcessing/indentation/force.dat
