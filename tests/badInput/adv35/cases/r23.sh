#!/bin/bash
# r23: blast: restart with shearViscosity changed in solidProperties
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; echo "shearViscosity 0.1;" >> constant/solidProperties
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted" | head; echo "rc=${PIPESTATUS[0]}"
