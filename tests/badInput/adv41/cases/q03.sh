#!/bin/bash
# q03: OpenFOAM's `postProcess -func 'mag(U)'` and `postProcess -func writeCellCentres -latestTime` (new fields written into the time directories, the documented use) over a finished blast case; then a restart to 3 ns, then -overwrite from 0: refused naming the added fields, or accepted; results kept?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
tryf "postProcess -func mag(U)" postProcess -func 'mag(U)'; nochange ../before
tryf "postProcess -func writeCellCentres -latestTime" postProcess -func writeCellCentres -latestTime; nochange ../before
latest; blastEnd 3e-9 1e-9; tryf "restart to 3e-9" cellBlastFoam; echo "   times: $(ls -d [0-9]* | tr '\n' ' '); 1e-09: $(ls 1e-09 | tr '\n' ' ')"
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sums > ../before2
tryf "-overwrite from 0" cellBlastFoam -overwrite; echo "   2e-09: $(ls 2e-09 2>/dev/null | tr '\n' ' ')"; ls postProcessing | tr '\n' ' '; echo
