#!/bin/bash
# o19: blast: -overwrite over a finished case with fluidProbes fields (pp)
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before; EDITED=controlDict; sed -i 's/fields          (p);/fields (pp);/' system/controlDict
cellBlastFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -A2 "FATAL" log.ow | head -3; sums | grep -v "$EDITED" > ../after; grep -v "$EDITED" ../before | diff - ../after | grep "^>" | sed "s/^> [0-9a-f]*  /changed: /" ; echo "diff done"
