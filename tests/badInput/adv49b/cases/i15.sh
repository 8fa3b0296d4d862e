#!/bin/bash
# i15 (class 4, values valid alone but not together): in a blast copy run for 2e-11 s (short): (a) predictor extrapolated with
# scheme explicitStaggered (the user guide: "iterative schemes only"), (b) predictor extrapolated with scheme aitken and
# maxIter 1, (c) solidSubcycles 1000 with scheme explicitStaggered, (d) predictor extrapolated with onNonConvergence stop and
# tolerance 1e-300 (below the reader? 1e-300 is in range). (a) refused naming both entries (or accepted with a warning that
# says the predictor is not used); never silently ignored; no crash in any.
. "$(dirname "$0")/../lib.sh"
blast; short; cp constant/fsiProperties ../f0
for e in "scheme explicitStaggered|predictor extrapolated" "scheme aitken|maxIter 1|predictor extrapolated" "scheme explicitStaggered|solidSubcycles 1000" "predictor extrapolated|onNonConvergence stop|tolerance 1e-300"; do
  cp ../f0 constant/fsiProperties; IFS='|' read -ra kv <<< "$e"; for x in "${kv[@]}"; do fsiSet $x > /dev/null; done
  tryt 200 "[$e]" cellBlastFoam; echo "   $(grep -a -i -m2 'predictor\|warn' $W/try.log | cut -c1-200 | tr '\n' '|')"; echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; rm -rf [1-9]* solid postProcessing; done
