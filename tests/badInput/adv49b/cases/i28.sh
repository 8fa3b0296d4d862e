#!/bin/bash
# i28 (class 3/2, Allclean while the solver runs, without an Allrun): bd restarted to 6e-9 (4 ns of run, cellBlastFoam started
# by hand, holding the lock); while it runs, the preview's ./Allclean: refused naming the running process, nothing removed;
# the run ends exit 0 with every time 1e-09..6e-09 and solid.h5 whole. Then (b) while a second restart runs, `./Allrun
# $PREV -noRun` (another preparation): refused, nothing changed.
. "$(dirname "$0")/../lib.sh"
bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; latest; blastEnd 6e-9 1e-9; cellBlastFoam > log.run 2>&1 & p=$!; waitFor 60 test -f .runLock; sleep 1; echo "   lock: $(lockOf)"
tryt 60 "(a) Allclean during the run" ./Allclean; echo "   left now: $(ls -d [0-9]* solid postProcessing 2>/dev/null | tr '\n' ' ')"
wait $p; echo "   run exit $? | $(tail -2 log.run | head -1 | cut -c1-120)"; after; echo "   solid.h5 steps $(h5steps solid/solid.h5), xmf $(xmfsteps solid/solid.xmf)"
latest; blastEnd 9e-9 1e-9; cellBlastFoam > log.run2 2>&1 & p=$!; waitFor 60 test -f .runLock; sums > ../s0
tryt 120 "(b) Allrun -noRun during a run" ./Allrun $PREV -noRun; echo "   said: $(grep -a -m1 -i "lock\|in use\|error" $W/try.log | cut -c1-220)"; echo "   changed meanwhile (the run's own files expected): $(changed ../s0 | tr ' ' '\n' | grep -v '^./[0-9]\|postProcessing\|solid/' | tr '\n' ' ')"; wait $p; echo "   run exit $?"
