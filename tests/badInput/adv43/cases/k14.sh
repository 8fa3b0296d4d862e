#!/bin/bash
# k14 (class 2, a restart that cuts back over a later segment holding the user's files): a blast to 2 ns, restarted to 3 ns (segments fsi/2e-09, solidProbes/2e-09, ...); the user's notes.md in fsi/2e-09/ and plot.png in solidProbes/2e-09/ AFTER it; the user removes times 2e-09 and 3e-09 (foamListTimes -rm) and restarts from 1e-09 to 3 ns: the user's files kept or refused by name (not removed with the cut-back segments)? the result equal to a clean restart from 1e-09?
. "$(dirname "$0")/../lib.sh"
blastDone; cp -r . ../ref1; latest; blastEnd 3e-9 1e-9; cellBlastFoam > log.second 2>&1; echo "   restart to 3 ns rc $?; segments: $(ls postProcessing/fsi | tr '\n' ' ')"
echo "# k14 my seg notes" > postProcessing/fsi/2e-09/notes.md; echo "k14 png" > postProcessing/solidProbes/2e-09/plot.png
foamListTimes -rm -time '2e-09:' > /dev/null 2>&1; echo "   times now: $(ls -d [0-9]* | tr '\n' ' ')"; sums > ../s
tryf "restart from 1e-09 to 3 ns" cellBlastFoam; grep -a 'postProcessing' $W/try.log | grep -v '^-->' | head -4 | cut -c1-160; echo "   times $(ls -d [1-9]* | tr '\n' ' '); segments: $(ls postProcessing/fsi | tr '\n' ' ')"; kept "k14 my seg notes" "k14 png"
(cd ../ref1 && rm -rf 2e-09 && latest && blastEnd 3e-9 1e-9 && cellBlastFoam > log.r 2>&1; echo "   clean restart from 1e-09: rc $?"); [ -d 3e-09 ] && cmpRef ../ref1
