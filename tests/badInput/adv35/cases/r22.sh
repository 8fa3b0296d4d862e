#!/bin/bash
# r22: blast: restart with hourglassViscosity changed
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/solidProperties hourglassViscosity 0.3
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"
