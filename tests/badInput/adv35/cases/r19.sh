#!/bin/bash
# r19: blast: restart with the pulse table of the latest time's p edited
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; sed -i 's/^(1e-10 50000000)/(1e-10 60000000)/; s/^(5.0000000000000001e-09 50000000)/(5.0000000000000001e-09 60000000)/' 2e-09/p; grep -ac 60000000 2e-09/p
cellBlastFoam 2>&1 | grep -iA3 "error\|changed\|restarted\|digest" | head; echo "rc=${PIPESTATUS[0]}"
