#!/bin/bash
# v35: Allrun locks: a cellIndentationFoam started by hand while the Allrun's solver runs
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
stopAll() { kill -KILL -- -$ap 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; wait $ap 2>/dev/null; }
startAllrun; cellIndentationFoam > log.hand 2>&1; echo "hand solver rc=$?"; grep -a -A2 FATAL log.hand | head -3 | cut -c1-300; stopAll
