#!/bin/bash
# g65 (class 1/2, a restart whose endTime is not after its start) bd (finished at 2e-09), startFrom latestTime with (a) endTime 2e-9 (equal to the latest time), (b) endTime 1.5e-9 (before it), (c) endTime 2.0000000000000004e-9 (one ulp after): (a) and (b) say there is nothing to run (or refuse naming endTime and the latest time) and change nothing; (c) runs at most one short step and writes a whole time, or refuses; never a time directory written before the latest one, never results changed silently.
. "$(dirname "$0")/../lib.sh"
bd; latest; sums > ../s0
for e in 2e-9 1.5e-9 2.0000000000000004e-9; do blastEnd $e 1e-9; tryt 120 "endTime $e" cellBlastFoam; tail -2 $W/try.log | cut -c1-150; echo "   changed: $(changed ../s0)"; done; after
