#!/bin/bash
# g50 (class 3, planeWave -check on a run still going and on a restarted run) bd (2 ns) restarted to 3e-9: planeWave -check (a) before, (b) while the restart runs (the probe logs growing), (c) after: (b) refused (the case is in use) or it checks the committed part and says which; (c) uses both segments (to 3e-9). Never an error measure from a half-written row.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; tryt 120 "(a) before the restart" planeWave -case . -check; tail -4 $W/try.log | cut -c1-200
cellBlastFoam > ../run.log 2>&1 & p=$!; waitFor 60 test -d postProcessing/fluidProbes/2e-09; sleep 3; tryt 120 "(b) during the restart" planeWave -case . -check; tail -4 $W/try.log | cut -c1-200; wait $p; echo "   run rc=$?"
tryt 120 "(c) after the restart" planeWave -case . -check; tail -4 $W/try.log | cut -c1-200; ls postProcessing/planeWave 2>/dev/null | tr '\n' ' '
