#!/bin/bash
# g54 (class 2/3, solidToFoam on a restarted run, then a further restart) bd restarted to 3e-9, solidToFoam (solid times 1e-09..3e-09), a second restart to 4e-9 (startFrom latestTime: the documented restart after the Allrun's solidToFoam step), solidToFoam again: the restart continues from 3e-09 (exit 0), solid.h5 has 4 steps, the second solidToFoam gives 4 solid times; or the restart refuses naming what solidToFoam wrote and how to go on.
. "$(dirname "$0")/../lib.sh"
bd; rs; tryt 240 "restart to 3e-9" cellBlastFoam; tryt 120 "solidToFoam (1)" solidToFoam solid/solid.h5; echo "   solid times: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' ')"
blastEnd 4e-9 1e-9; tryt 240 "restart to 4e-9 after solidToFoam" cellBlastFoam; cont; after; tryt 120 "solidToFoam (2)" solidToFoam solid/solid.h5; echo "   solid times: $(ls -d [0-9]*/solid 2>/dev/null | tr '\n' ' ')"
