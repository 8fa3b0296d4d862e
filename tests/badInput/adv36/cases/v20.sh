#!/bin/bash
# v20: ind: 1 row appended to force.dat beyond the checkpoint (a killed run's rows) plus a garbage row, then a restart
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict ; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 2.5; kill -KILL $p; wait $p 2>/dev/null; printf '99 1 2 3 4 X\ngarb\x00age' >> postProcessing/indentation/force.dat
cellIndentationFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8; grep -ac "garb\|^99 " postProcessing/indentation/force.dat; tail -1 postProcessing/indentation/force.dat
