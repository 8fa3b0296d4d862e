#!/bin/bash
# v34: Allrun locks: two Allruns of the indentation tutorial (full protocol) at once in one copy
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
stopAll() { kill -KILL -- -$ap 2>/dev/null; pkill -KILL -s $ap 2>/dev/null; wait $ap 2>/dev/null; }
startAllrun; ./Allrun > log.allrun2 2>&1; echo "second Allrun rc=$?"; head -4 log.allrun2 | cut -c1-300; echo "first still running: $(ps -o comm= -p $ap)"; ls log.*; stopAll
