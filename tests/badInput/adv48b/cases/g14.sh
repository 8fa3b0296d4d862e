#!/bin/bash
# g14 (class 3/6, the lock: a huge file) bd restart with .runLock a sparse 8 GiB file (no data, the size of a damaged or foreign file): refused within seconds naming .runLock as not a lock (damaged), never read whole (memory), never taken over; the same for solidToFoam.
. "$(dirname "$0")/../lib.sh"
bd; rs; truncate -s 8G .runLock; sums > ../s0
tryt 120 "cellBlastFoam, .runLock 8 GiB sparse" /usr/bin/time -f "maxRSS %M kB" cellBlastFoam; grep -a maxRSS $W/try.log; echo "   changed: $(changed ../s0)"; after
tryt 120 "solidToFoam, .runLock 8 GiB sparse" /usr/bin/time -f "maxRSS %M kB" solidToFoam solid/solid.h5; grep -a maxRSS $W/try.log; ls -la .runLock | awk '{print "   lock size", $5}'
