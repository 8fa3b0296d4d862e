#!/bin/bash
# r13: blast: restart with coupling scheme robin -> aitken
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/fsiProperties coupling/scheme aitken
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head; echo "rc=${PIPESTATUS[0]}"
