#!/bin/bash
# g35 (class 4/6, time steps no run can finish) the prepared preview, endTime 2e-11, with (a) deltaT 1e-299 and adjustTimeStep no, (b) maxDeltaT 1e-299 (adjustTimeStep yes), (c) deltaT 4.9e-324: each refused before the run, naming the entry and the number of steps it means (or the range), or bounded; never a run that cannot end (200 s: HANG).
. "$(dirname "$0")/../lib.sh"
blast; short
for e in "deltaT 1e-299|adjustTimeStep no" "maxDeltaT 1e-299" "deltaT 4.9e-324|adjustTimeStep no"; do cp system/controlDict ../cd0; IFS='|' read -ra kv <<< "$e"; for x in "${kv[@]}"; do sete system/controlDict ${x%% *} "${x#* }"; done
  tryt 200 "$e" cellBlastFoam; tail -1 $W/try.log | cut -c1-150; echo "   times: $(ls -d [1-9]* 2>/dev/null | wc -l)"; rm -rf [1-9]* solid postProcessing; cp ../cd0 system/controlDict; done
