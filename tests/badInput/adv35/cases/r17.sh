#!/bin/bash
# r17: blast: restart with reconstruct(p) MUSCL -> vanLeer in fvSchemes
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; sed -i 's/reconstruct(p)      MUSCL;/reconstruct(p) vanLeer;/' system/fvSchemes
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"
