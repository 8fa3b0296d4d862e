#!/bin/bash
# x01: nested Allruns: a user's Allrun.outer (takes the lock with etc/RunFunctions allrunLock, then calls ./Allrun) around the indentation Allrun (10x finer steps): the lock chain while the solver runs, a hand-started solver refused, the lock gone at the end, force.dat times increasing?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
printf '#!/bin/bash\ncd "${0%%/*}" || exit 1\n. "$WM_PROJECT_DIR"/bin/tools/RunFunctions\n. "$PROJECT_DIR"/etc/RunFunctions\nallrunLock\n./Allrun\n' > Allrun.outer; chmod +x Allrun.outer
./Allrun.outer > log.outer 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; echo "lock while the solver runs: $(lockOf)"
run 60 cellIndentationFoam > log.hand 2>&1; fatal log.hand 3
wait $p; echo "outer exit $?"; echo "after: $(lockOf)"; tail -2 log.outer
awk '!/^#/{if(NR>1&&$1<t)bad++; t=$1} END{print "force.dat rows", NR, "times going back:", bad+0}' postProcessing/indentation/force.dat
