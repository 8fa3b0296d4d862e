#!/bin/bash
# z02: blast finished to 2 ns (startFrom startTime): `cellBlastFoam -dry-run` and `-dry-run-write` (options of its -help: "check case set-up ... using a single time step", the second writes): refused as a new start over results, or harmless? every result unchanged? then a restart to 3 ns continues?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
try "-dry-run" cellBlastFoam -dry-run; echo "changed: $(changed ../before)"
try "-dry-run-write" cellBlastFoam -dry-run-write; echo "changed: $(changed ../before)"; ls -da [0-9]* .[0-9]* 2>/dev/null | tr '\n' ' '; echo
try "-dry-run-write -overwrite" cellBlastFoam -dry-run-write -overwrite; echo "changed: $(changed ../before)"; ls -da [0-9]* .[0-9]* 2>/dev/null | tr '\n' ' '; echo
latest; blastEnd 3e-9 1e-9; try "restart to 3e-9" cellBlastFoam; echo "times: $(ls -d [0-9]* | tr '\n' ' ')"
