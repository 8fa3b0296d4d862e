#!/bin/bash
# o20: blast: -overwrite over a finished case with shearViscosity 1 (out of range)
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before; EDITED=solidProperties; setd constant/solidProperties shearViscosity 1
cellBlastFoam -overwrite > log.ow 2>&1; echo "rc=$?"; grep -A2 "FATAL" log.ow | head -3; sums | grep -v "$EDITED" > ../after; grep -v "$EDITED" ../before | diff - ../after | grep "^>" | sed "s/^> [0-9a-f]*  /changed: /" ; echo "diff done"
