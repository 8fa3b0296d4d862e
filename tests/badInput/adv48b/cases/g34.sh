#!/bin/bash
# g34 (class 4/6, a write interval that forces a step no run can finish) the prepared preview (blast), controlDict.allrun writeInterval 1e-299 (adjustableRunTime: the steps are cut to hit every write time) and endTime 2e-11: refused before the run naming writeInterval (and how many writes/steps it means), or run to 2e-11 in bounded time; never a run that cannot end (killed here after 200 s: HANG). Then writeInterval 1e-13 (below deltaT 1e-12): runs to 2e-11 in bounded time, its writes listed.
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 2e-11 1e-299; tryt 200 "writeInterval 1e-299" cellBlastFoam; tail -2 $W/try.log | cut -c1-150; echo "   times: $(ls -d [0-9]* | wc -l)"; rm -rf [1-9]* solid postProcessing
blastEnd 2e-11 1e-13; tryt 200 "writeInterval 1e-13" cellBlastFoam; tail -2 $W/try.log | cut -c1-150; echo "   times: $(ls -d [0-9]* | wc -l)"
