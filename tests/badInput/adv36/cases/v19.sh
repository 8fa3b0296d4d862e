#!/bin/bash
# v19: ind: materials.dat edited (one digit) after a kill, then a restart
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict ; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 2.5; kill -KILL $p; wait $p 2>/dev/null; f=postProcessing/indentation/materials.dat; head -3 $f; sed -i 's/^nucleus 1000 6.66/nucleus 1000 9.66/' $f; grep nucleus $f
cellIndentationFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A6 FATAL log.r | head -8
echo "after the restart: $(grep nucleus postProcessing/indentation/materials.dat)"
