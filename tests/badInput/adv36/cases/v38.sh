#!/bin/bash
# v38: Allrun locks: the Allrun's shell sent SIGTERM (as a user's kill) while its solver runs: the lock, the solver, and a second start
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
stopAll() { kill -KILL -- -$ap 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; wait $ap 2>/dev/null; }
startAllrun; sp=$(pgrep -s $ap cellIndent | head -1); kill -TERM $ap; sleep 1; echo "allrun alive: $(ps -o comm= -p $ap) solver alive: $(ps -o comm= -p $sp) lock: $(head -1 .runLock 2>&1)"
timeout 20 cellIndentationFoam > log.hand 2>&1; echo "hand solver rc=$?"; grep -a -A2 "FATAL\|Removing" log.hand | head -3 | cut -c1-250; kill -KILL $sp 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; true
