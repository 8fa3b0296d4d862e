#!/bin/bash
# g73 (class 3/6, the Python tools and the Allrun on a huge lock; g14's case for the Python side) a sparse 8 GiB .runLock in (a) a fresh preview copy: ./Allrun $PREV -noRun; (b) bd: planeWave -case . -check; (c) bd: sweepCase -case . (one value, -run true): each refused within seconds naming .runLock as no lock (its size), never read whole (maxRSS printed), never taken over (60 s each: HANG).
. "$(dirname "$0")/../lib.sh"
prev; truncate -s 8G .runLock; tryt 60 "(a) Allrun -noRun" /usr/bin/time -f "maxRSS %M kB" ./Allrun $PREV -endTime 2e-9 -noRun; grep -a maxRSS $W/try.log | sed 's/^/   /'; echo "   lock size $(stat -c %s .runLock)"
bd; truncate -s 8G .runLock; tryt 60 "(b) planeWave -check" /usr/bin/time -f "maxRSS %M kB" planeWave -case . -check; grep -a maxRSS $W/try.log | sed 's/^/   /'
tryt 60 "(c) sweepCase" /usr/bin/time -f "maxRSS %M kB" sweepCase -case . -entry constant/fsiProperties/coupling/maxIter -values "31" -output "x=postProcessing/fsi/0/coupling.dat:max:2" -run true -name big; grep -a maxRSS $W/try.log | sed 's/^/   /'; killIn $W; echo "   lock size $(stat -c %s .runLock)"
