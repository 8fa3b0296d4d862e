#!/bin/bash
# g36 (class 2, g35's mechanism during a live run): a fresh blast run to 6 ns (a commit every 1 ns); once 1e-09 is committed the user writes notes.txt (plain text) into postProcessing/fsi/0/ and plot.png into postProcessing/solidProbes/0/ while the run goes on; the run ends; what do the later commit markers record? then -overwrite from 0 (a new start over the results): are the user's files refused by name, or recorded as the run's logs and removed?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 6e-9 1e-9; cellBlastFoam > log.first 2>&1 & p=$!; waitFor 60 test -f 1e-09/.writeCommitted; printf 'g36 notes during the run\n' > postProcessing/fsi/0/notes.txt; printf 'g36 png\n' > postProcessing/solidProbes/0/plot.png; wait $p; echo "   run rc $?: times $(ls -d [1-9]* | tr '\n' ' ')"
echo "   markers naming the user's files: $(grep -a -l 'notes.txt\|plot.png' */.writeCommitted 2>/dev/null | tr '\n' ' ')"
blastEnd 2e-9 1e-9; tryf "-overwrite from 0" cellBlastFoam -overwrite; kept "g36 notes during the run" "g36 png"
