#!/bin/bash
# CASETIMEOUT=900
# n37 (new, class 3/5: the readers beside a KILLED run's stale lock - a regression check for readers that refuse a case
# "whose run goes on"): the preview restarted to 20e-9 and SIGKILLed at 8 s (its .runLock left, its process gone); then
# plotBlast.py, incidentWindow.py, planeWave -case . -partial, planeWave -check, and the same after the lock file's host
# field names another machine. Expected: the killed run read as a cut run (said partial / killed), never "the run goes
# on" for a dead process; the lock of another host named with its host.
. "$(dirname "$0")/../lib.sh"
p8; blastEnd 20e-9 1e-9; rm -f .runLock; cellBlastFoam > log.cellBlastFoam 2>&1 & p=$!; sleep 8; kill -KILL $p; wait $p 2>/dev/null
echo "   killed: times $(ls -d [0-9]* | tr '\n' ' ' | cut -c1-150) | lock: $(head -c 150 .runLock 2>/dev/null | tr '\n' ' ')"
rd() { tryt 300 "$1" "${@:2}"; echo "   said: $(say 2 | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-150)"; }
rd "(a) plotBlast.py" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .
rd "(a) incidentWindow.py" /usr/bin/python3 $ROOT/bench/blast/analysis/incidentWindow.py .
rd "(a) planeWave -partial" planeWave -case . -partial
rd "(a) planeWave -check" planeWave -case . -check
[ -f .runLock ] && sed -i 's/host [^ ]*/host othermachine/' .runLock && echo "   lock now: $(head -c 150 .runLock | tr '\n' ' ')"
rd "(b) plotBlast.py, another host's lock" /usr/bin/python3 $ROOT/tutorials/blast/plotBlast.py .
rd "(b) planeWave -partial, another host's lock" planeWave -case . -partial
