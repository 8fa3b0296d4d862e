#!/bin/bash
# x10: Ctrl-C (SIGINT to the whole process group) of the indentation Allrun while its solver runs, then ./Allrun again: the lock? what does the second Allrun say and do (the first run's partial results: start anew over them, refuse, continue)?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
/usr/bin/python3 -c "import signal,os; signal.signal(signal.SIGINT, signal.SIG_DFL); os.setsid(); os.execvp(\"./Allrun\", [\"./Allrun\"])" > log.a1 2>&1 & p=$!
waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 1; kill -INT -- -$p; wait $p; echo "Allrun exit $? after SIGINT; lock: $(lockOf)"; ls log.* | tr '\n' ' '; echo; tail -3 log.a1 | cut -c1-200
n1=$(grep -vc '^#' postProcessing/indentation/force.dat); echo "force rows $n1"
run 120 ./Allrun > log.a2 2>&1; echo "second Allrun:"; grep -a -v "^\s*$" log.a2 | head -12 | cut -c1-250; echo "force rows now $(grep -vc '^#' postProcessing/indentation/force.dat)"
