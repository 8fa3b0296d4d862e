#!/bin/bash
# o18: blast: -overwrite over a finished case with an unknown region in solidProperties interfaces
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before; EDITED=solidProperties; sed -i 's/^interfaces .*/interfaces ((membrane cytoplasma));/' constant/solidProperties
cellBlastFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -A2 "FATAL" log.ow | head -3; sums | grep -v "$EDITED" > ../after; grep -v "$EDITED" ../before | diff - ../after | grep "^>" | sed "s/^> [0-9a-f]*  /changed: /" ; echo "diff done"
