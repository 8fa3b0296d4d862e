#!/bin/bash
# CASETIMEOUT=600
# n10 (new, class 3/5: adv53 l05's class in the indentation: a plot script on a case whose solver is running): the smoke
# indentation (ind) with 10x finer steps started in the background; after 3 s (rows written, the run going on):
# plotIndentation.py on it, then again after the run's end. Expected: the first refused or said "the run is going on /
# partial" naming the lock; a table of the partial run rc 0 without a word = SILENT (as l05).
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.run 2>&1 & p=$!
sleep 3; echo "   running: $(kill -0 $p 2>/dev/null && echo yes || echo no) | lock: $(head -c 120 .runLock 2>/dev/null | tr '\n' ' ') | force rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null)"
pi; echo "   (a) during the run: $(pk) | said: $(grep -a -i -m2 'running\|partial\|lock\|not finished\|error' $W/try.log | tr '\n' '|' | cut -c1-250)"; echo "   still running: $(kill -0 $p 2>/dev/null && echo yes || echo no)"
wait $p; echo "   the run: rc $? End $(grep -a -c '^End' log.run)"; pi; echo "   (b) after it: $(pk)"
