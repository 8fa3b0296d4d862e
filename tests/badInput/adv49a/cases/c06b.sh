#!/bin/bash
# c06b (adv35 c06 redone longer: in this pass's run (load 15) the SIGKILL at 0.6 s landed before cellIndentationFoam wrote
# its lock, so the stale lock was not tested): the same case with the kill once the lock and the first checkpoint exist
# (waitFor, at most 60 s), then the restart: the stale lock of the dead pid replaced with a message, the run continues
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.02e-6/' constant/indenterProperties; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; echo "checkpointInterval 1;" >> system/controlDict
cellIndentationFoam > log.a 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/restart.h5; kill -9 $p; wait $p; ls -a | tr '\n' ' '; echo; cat .runLock 2>/dev/null
cellIndentationFoam > log.b 2>&1; echo "restart rc=$?"; grep -i "lock\|restarted\|FATAL" log.b | head -5; tail -1 log.b
