#!/bin/bash
# x70: indentation Allrun (fine steps): its SOLVER alone SIGKILLed (the OOM killer) inside the live Allrun: the Allrun's exit, the lock after, and the next ./Allrun: it re-runs the solver over the partial results (resultGuard asks for -overwrite, which an Allrun cannot pass?) - is the way out said?
. "$(dirname "$0")/../lib.sh"
indAllrun; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
./Allrun > log.a1 2>&1 & p=$!; waitFor 120 test -f postProcessing/indentation/restart.h5; s=$(sed -n 's/^pid //p' .runLock | head -1); echo "lock names $(sed -n 's/^executable //p' .runLock | head -1) $s"; kill -KILL $s; wait $p; echo "Allrun exit $?; lock after: $(lockOf)"; tail -2 log.a1 | cut -c1-200; ls log.* | tr '\n' ' '; echo
run 120 ./Allrun > log.a2 2>&1; echo "second Allrun:"; grep -a -v "^\s*$" log.a2 | grep -a -v "^\s*From\|in file" | head -12 | cut -c1-250
