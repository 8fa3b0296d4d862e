#!/bin/bash
# v39: Allrun locks: ./Allclean of the case while its Allrun's solver runs (the Allrun's output kept outside the case)
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
startAllrun() { setsid ./Allrun > ../log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1; }
startAllrun; ./Allclean > ../log.clean 2>&1; echo "Allclean rc=$?"; head -3 ../log.clean | cut -c1-250; ls; sleep 2; echo "Allrun alive: $(ps -o comm= -p $ap)"; wait $ap; echo "Allrun rc=$?"; tail -5 ../log.allrun | cut -c1-250; pkill -KILL -s $ap 2>/dev/null; true
