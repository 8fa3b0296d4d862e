#!/bin/bash
# z06: a lock holder STOPPED (SIGSTOP, as Ctrl-Z in its terminal): an indentation (10x finer steps) stopped after its first checkpoint; a second cellIndentationFoam and cellMesh started: refused (the process lives), not taken over as stale? then SIGCONT: the first run ends well, force.dat times increasing, lock gone?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/restart.h5; kill -STOP $p; echo "stopped $p; lock: $(lockOf)"
try "second solver" cellIndentationFoam; try "cellMesh" cellMesh; echo "lock now: $(lockOf)"
kill -CONT $p; wait $p; echo "first run exit $?; $(tail -1 log.first)"; echo "lock after: $(lockOf)"
forceOk postProcessing/indentation/force.dat
