#!/bin/bash
# CASETIMEOUT=900
# p14 (new, class 6/2: a CPU-time limit, `ulimit -t`, SIGXCPU in the middle of a run): (a) bd restarted to 6e-9 under
# ulimit -t 20 (s of CPU); then without the limit, the restart again to 6e-9: it continues from the last committed time
# and ends; (b) the killed indentation (ik) restarted under ulimit -t 3, then without. Each: the limit's stop leaves the
# case restartable (no half-written time taken as good, the stale lock taken over, said), the second run ends rc 0;
# results lost or a restart refused for a reason the user cannot act on = DATALOSS / UNCLEAR.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 6e-9 1e-9; rm -f .runLock
tryt 300 "(a1) restart to 6e-9 under ulimit -t 20" bash -c "ulimit -t 20; exec cellBlastFoam"; echo "   sig lines: $(sig) | last: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-200)"
echo "   after: times $(ls -d [0-9]* .[0-9]* *.incomplete 2>/dev/null | tr '\n' ' ') | solid.h5 steps $(h5steps solid/solid.h5) | lock: $(lockOf | cut -c1-80)"
tryt 600 "(a2) the restart again without the limit" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250) | stale lock said: $(grep -a -c -i 'stale' $W/try.log)"
echo "   now: times $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ') | solid.h5 steps $(h5steps solid/solid.h5)"
cd $W; ik; tryt 300 "(b1) indentation restart under ulimit -t 3" bash -c "ulimit -t 3; exec cellIndentationFoam"; echo "   sig lines: $(sig) | last: $(tail -1 $W/try.log | cut -c1-200)"; after
tryt 600 "(b2) again without the limit" cellIndentationFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-250)"; after
