#!/bin/bash
# r12: blast: restart with coupling tolerance changed
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/fsiProperties coupling/tolerance 1e-3
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head; echo "rc=${PIPESTATUS[0]}"
