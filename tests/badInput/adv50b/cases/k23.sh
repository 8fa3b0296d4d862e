#!/bin/bash
# k23 (class 3, incidentWindow.py and planeWave while a restart of the same case writes): pw restarted to 30e-9 in the background; incidentWindow.py on it while it runs. Expected: it reads only committed rows or names the run as running; the run is undisturbed.
. "$(dirname "$0")/../lib.sh"
pwd0; latest; blastEnd 30e-9 1e-9; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 2
iw .; head -5 $W/try.log | cut -c1-180 | sed 's/^/   /'; echo "   run alive: $(kill -0 $p 2>/dev/null && echo yes || echo no)"; kill -TERM $p; wait $p; echo "   run rc=$? (SIGTERM by the case)"; after
