#!/bin/bash
# v69: Allrun locks: the Allrun's shell sent SIGTERM while its solver runs (checkpointInterval 1, startFrom latestTime): its EXIT trap removes the lock, the solver goes on; then cellIndentationFoam by hand: two solvers in one case at once, force.dat of both
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/indentation/averageCell" "$W/al"; cd "$W/al"; cp "$ADV/indBase/constant/cell.msh" constant/; sed -i "s/^runStep cellMesh/#&/" Allrun
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; echo "checkpointInterval 1;" >> system/controlDict
setsid ./Allrun > ../log.allrun 2>&1 & ap=$!; for i in $(seq 50); do [ -f log.cellIndentationFoam ] && break; sleep 0.2; done; sleep 1
sp=$(pgrep -s $ap cellIndent | head -1); kill -TERM $ap; sleep 1; echo "Allrun alive: '$(ps -o comm= -p $ap)'; its solver $sp alive: '$(ps -o comm= -p $sp)'; .runLock: $(head -1 .runLock 2>&1)"
cellIndentationFoam > log.hand 2>&1 & hp=$!
for i in 1 2 3 4 5 6; do sleep 0.5; echo "t+$i/2 s: orphan '$(ps -o comm= -p $sp)' hand '$(ps -o comm= -p $hp)'"; done
grep -a "Continuing" log.hand | cut -c1-200; echo "orphan's end:"; grep -a -A1 "FATAL" log.cellIndentationFoam | cut -c1-250
kill -KILL $hp $sp 2>/dev/null; wait $hp 2>/dev/null
echo "force.dat rows whose time does not increase:"; awk '!/^#/{ if (n++ && $1+0 <= prev+0) print "  line " NR ": " prev " -> " substr($0,1,60); prev=$1 }' postProcessing/indentation/force.dat | head -5
