#!/bin/bash
# z19: the blast Allrun's own post-processing done by hand on a finished run (solidToFoam solid/solid.h5 writes <t>/solid into the committed times; foamToVTK), then the documented restart to 3 ns (startFrom latestTime): continues? then -overwrite from 0: accepted (solidToFoam's folders are known) and nothing of the user's lost?
. "$(dirname "$0")/../lib.sh"
blastDone; solidToFoam solid/solid.h5 > log.s2f 2>&1; echo "solidToFoam rc=$?; 2e-09: $(ls -a 2e-09 | tr '\n' ' ')"; foamToVTK > log.vtk 2>&1; echo "foamToVTK rc=$?"
latest; blastEnd 3e-9 1e-9; try "restart to 3e-9" cellBlastFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
solidToFoam solid/solid.h5 > log.s2f2 2>&1; echo "solidToFoam again rc=$?"
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; try "-overwrite" cellBlastFoam -overwrite; echo "   times: $(ls -da [1-9]* .[1-9]* 2>/dev/null | tr '\n' ' ')"
