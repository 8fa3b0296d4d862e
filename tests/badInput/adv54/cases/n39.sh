#!/bin/bash
# CASETIMEOUT=900
# n39 (new, class 3/5: the documented way to measure a run going on - planeWave -partial, incidentWindow.py on a copy -
# as a regression check for readers that refuse a running case): p8 restarted to 30e-9 in the background; once it has
# written 1e-08: planeWave -case . -partial, planeWave -case . (without -partial), incidentWindow.py, plotBlast.py, and a
# `cp -a` of the running case measured with planeWave -partial (the copy's lock names the live process of the original).
# Expected: -partial measures the run so far saying so; the others refuse naming the run (or measure saying partial); the
# copy: measured as a cut run or refused naming the ORIGINAL's process (not its own); the run undisturbed (End).
. "$(dirname "$0")/../lib.sh"
p8; blastEnd 30e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 & p=$!
for i in $(seq 1 600); do [ -f 1e-08/.writeCommitted ] && break; sleep 0.2; done; echo "   running: $(kill -0 $p 2>/dev/null && echo yes || echo no) | times $(ls -d [0-9]* | wc -l)"
rd() { tryt 300 "$1" "${@:2}"; echo "   said: $(say 2 | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-150)"; }
rd "(a) planeWave -partial on the running case" planeWave -case . -partial
rd "(b) planeWave without -partial" planeWave -case .
rd "(c) incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .
rd "(d) plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .
cp -a $W/p8 $W/copy 2>/dev/null; cd $W/copy; rd "(e) planeWave -partial on a copy of the running case" planeWave -case . -partial; cd $W/p8
wait $p; echo "   the run: rc $? End $(grep -a -c '^End' log.cellBlastFoam)"
