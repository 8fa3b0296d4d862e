#!/bin/bash
# CASETIMEOUT=900
# p25 (new, class 3: two cases whose result folders are one folder through a symbolic link, run at once; each case has
# its own lock): bd copied to A and B, B/solid replaced by a link to A/solid (a user saving space, or a script linking
# results); both restarted to 4e-9 at once (startFrom latestTime). Then (b) the same with B/postProcessing a link to
# A/postProcessing. Expected: the second refused (the result folder is in use by the first: the lock of the folder it
# writes, or its real path compared), or each run's files whole; two runs writing one solid.h5 or one coupling.dat
# (steps or rows of both, A's results no longer A's) = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 4e-9 1e-9; rm -f .runLock; cd $W; mv blast A; cp -a A B
two() { cd $W/A; (cellBlastFoam > log.A 2>&1; echo "A rc $?" >> log.A) & pa=$!; sleep 2; cd $W/B; tryt 400 "$1" cellBlastFoam; wait $pa
  echo "   A: $(tail -1 $W/A/log.A) $(grep -a -m1 -i 'fatal\|error' $W/A/log.A | cut -c1-150) | B: End $(grep -a -c '^End' $W/try.log) $(msg 3 | cut -c1-200)"
  echo "   A/solid/solid.h5 steps $(h5steps $W/A/solid/solid.h5) | A's times $(cd $W/A; ls -d [0-9]* | tr '\n' ' ') | A's coupling.dat rows $(grep -vc '^#' $W/A/postProcessing/fsi/0/coupling.dat) (duplicated times: $(grep -v '^#' $W/A/postProcessing/fsi/0/coupling.dat | awk '{print $1}' | sort | uniq -d | wc -l))"; }
cd $W/B; rm -rf solid; ln -s $W/A/solid solid; cd $W; cp -a A A0; cp -a B B0
two "(a) B (solid/ a link to A's) restarted while A runs"
cd $W; rm -rf A B; cp -a A0 A; cp -a A0 B; cd B; rm -rf postProcessing; ln -s $W/A/postProcessing postProcessing
two "(b) B (postProcessing/ a link to A's) restarted while A runs"
