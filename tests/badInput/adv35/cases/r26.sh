#!/bin/bash
# r26: blast: restart with the interfaces list changed (interface maxima columns)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; sed -i 's/^interfaces .*/interfaces ((membrane cytoplasm));/' constant/solidProperties
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"; head -3 postProcessing/solidInterfaces/*/* 2>/dev/null | cut -c1-150
