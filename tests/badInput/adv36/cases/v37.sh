#!/bin/bash
# v37: Allrun locks: the Allrun and its solver SIGKILLed together (process group), then ./Allrun again: the stale lock replaced, said so
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
stopAll() { kill -KILL -- -$ap 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; wait $ap 2>/dev/null; }
startAllrun; stopAll; cat .runLock | head -1; mv log.cellIndentationFoam log.old; sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict
startAllrun; sleep 1; echo "second Allrun running: $(ps -o comm= -p $ap)"; grep -a -i "stale\|in use\|error" log.allrun | head -3 | cut -c1-250; stopAll
