#!/bin/bash
# f05 (class 1, the latest time removed by the user, the logs and solid.h5 reaching beyond it): A = bd with 2e-09 deleted, restart latestTime (1e-09) to 3e-9; B = bd restarted from 2e-09 to 3e-9. Kill-and-restart is exact, so A must equal B (the four logs joined over restarts, solid.h5, 3e-09/p) or refuse naming what reaches beyond 1e-09; never a log with rows of both.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B restart from 2e-09" cellBlastFoam
bd; rs; rm -rf 2e-09; tryt 240 "A restart from 1e-09 (2e-09 deleted)" cellBlastFoam; cont; after; cmpRef $W/B
