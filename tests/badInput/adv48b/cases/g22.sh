#!/bin/bash
# g22 (class 2, the preview's Allrun interrupted) ./Allrun $PREV -endTime 2e-9 -noRun in its own process group, SIGINT to the group (Ctrl-C) 8 s after the start (in its meshing), then the same Allrun again: it finishes the preparation (no step skipped because a killed step left its log), and cellBlastFoam runs on the case (endTime 2e-11); or it refuses naming what to clean. Never a case that looks prepared and is not.
. "$(dirname "$0")/../lib.sh"
prev; set -m; ./Allrun $PREV -endTime 2e-9 -noRun > ../a1.log 2>&1 & p=$!; set +m; sleep 8; kill -INT -- -$p 2>/dev/null; sleep 3; kill -KILL -- -$p 2>/dev/null; wait $p 2>/dev/null; echo "   interrupted after: $(ls log.* 2>/dev/null | tr '\n' ' ')"; tail -2 ../a1.log | cut -c1-150
tryt 300 "Allrun again" ./Allrun $PREV -endTime 2e-9 -noRun; tail -4 $W/try.log | cut -c1-200; echo "   logs: $(ls log.* | tr '\n' ' ')"
blastEnd 2e-11 1e-11; tryt 200 "cellBlastFoam to 2e-11" cellBlastFoam; tail -2 $W/try.log | cut -c1-150; after
