#!/bin/bash
# v36: Allrun locks: the Allrun's shell SIGKILLed alone (its solver goes on as an orphan), then a solver and an Allrun started in the case
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
stopAll() { kill -KILL -- -$ap 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; wait $ap 2>/dev/null; }
startAllrun; sp=$(pgrep -s $ap -x cellIndentation | head -1); [ -z "$sp" ] && sp=$(pgrep -s $ap cellIndent | head -1); echo "solver pid $sp"; kill -KILL $ap; sleep 0.5; echo "orphan solver alive: $(ps -o comm= -p $sp)"; cat .runLock | head -3 | tr '\n' ' '; echo
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict
timeout 20 cellIndentationFoam > log.hand 2>&1; echo "hand solver rc=$?"; grep -a -A2 "FATAL\|stale\|Removing" log.hand | head -4 | cut -c1-300
echo "orphan still alive: $(ps -o comm= -p $sp)"; kill -KILL $sp 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; true
