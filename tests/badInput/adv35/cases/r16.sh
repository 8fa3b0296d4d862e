#!/bin/bash
# r16: blast: restart with the water's Gamma0 changed in thermophysicalProperties
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; setd constant/thermophysicalProperties mieGruneisenCoeffs/Gamma0 0.2
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head -8; echo "rc=${PIPESTATUS[0]}"
