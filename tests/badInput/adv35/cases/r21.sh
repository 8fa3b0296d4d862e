#!/bin/bash
# r21: blast: restart with solidSubcycles 1 -> 2
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/fsiProperties coupling/solidSubcycles 2
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head; echo "rc=${PIPESTATUS[0]}"
