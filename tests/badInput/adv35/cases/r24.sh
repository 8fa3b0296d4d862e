#!/bin/bash
# r24: blast: restart with interfaceProbe heightFraction changed (solid probe moves)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/solidProperties interfaceProbe/heightFraction 0.5
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"
