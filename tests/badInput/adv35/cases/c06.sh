#!/bin/bash
# c06: stale lock: restart after SIGKILL (lock left by a dead pid)
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; sleep 0.6; kill -9 $p; wait $p; ls -a; cat .runLock 2>/dev/null
cellIndentationFoam > log.b 2>&1; echo "restart rc=$?"; grep -i "lock\|restarted\|FATAL" log.b | head -5; tail -1 log.b
