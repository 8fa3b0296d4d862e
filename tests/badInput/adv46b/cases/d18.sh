#!/bin/bash
# d18 (class 2, cellBlastFoam -dry-run on the finished preview): OpenFOAM v1912 option "check case set-up only using a single time step": every result file unchanged (or a refusal over results), no new time.
. "$(dirname "$0")/../lib.sh"
bd; sums > ../s0; tryt 200 "-dry-run" cellBlastFoam -dry-run; echo "   $(tail -1 $W/try.log | cut -c1-150)"; nochange ../s0; after
