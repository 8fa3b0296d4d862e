#!/bin/bash
# x11: a machine reset during the indentation Allrun: the whole group SIGKILLed, the lock's host name then another (the container came back with a new host name); the recovery a user would follow from the messages: ./Allrun, rm the lock as told, ./Allrun, then the runStep advice (rm log.running, latestTime, solver by hand), then ./Allrun for the plots: results complete and equal to an uninterrupted run?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
setsid ./Allrun > log.a1 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 2; kill -KILL -- -$p; wait $p 2>/dev/null; sed -i 's/^host .*/host oldhost-1/' .runLock; echo "killed; lock: $(lockOf)"
run 60 ./Allrun > log.a2 2>&1; echo "A2: $(head -3 log.a2 | tr '\n' ' ' | cut -c1-300)"
rm -f .runLock; run 60 ./Allrun > log.a3 2>&1; echo "A3: $(head -3 log.a3 | tr '\n' ' ' | cut -c1-400)"
rm -f log.cellIndentationFoam.running; latest; run 200 cellIndentationFoam > log.hand 2>&1; tail -2 log.hand | tr '\n' ' '; echo
run 200 ./Allrun > log.a4 2>&1; echo "A4: $(tail -3 log.a4 | tr '\n' ' ' | cut -c1-300)"; ls log.* | tr '\n' ' '; echo
cp -r $ROOT/tutorials/indentation/averageCell $W/ref; cd $W/ref; /usr/bin/python3 $ROOT/tests/lib/setProtocol.py constant/indenterProperties --smoke; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellMesh > log.m 2>&1; cellIndentationFoam > log.r 2>&1
cmp $W/ia/postProcessing/indentation/force.dat postProcessing/indentation/force.dat && echo "force.dat equal to the uninterrupted run"; cmp $W/ia/postProcessing/indentation/peaks.dat postProcessing/indentation/peaks.dat && echo "peaks.dat equal"
