#!/bin/bash
# r11: blast: finished at 2 ns, restart latestTime to 3 ns (baseline: continues)
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9
cellBlastFoam 2>&1 | grep -i "continu\|restart\|error\|End" | head; echo "rc=${PIPESTATUS[0]}"; ls
