#!/bin/bash
# v22: blast: the middle time 1e-9 without its marker and its p zeroed, started from it (startFrom startTime; startTime 1e-9)
. "$(dirname "$0")/../lib.sh"
blastDone; rm 1e-09/.writeCommitted; dd if=/dev/zero of=1e-09/p bs=1 seek=2000 count=64 conv=notrunc 2>/dev/null; setd system/controlDict startTime 1e-9; blastEnd 3e-9 1e-9
cellBlastFoam > log.r 2>&1; echo "restart rc=$?"; grep -a -A8 FATAL log.r | head -10
echo "-- the same with -overwrite:"; cellBlastFoam -overwrite > log.r2 2>&1; echo "overwrite from 1e-9 rc=$?"; grep -a -A4 FATAL log.r2 | head -6 | cut -c1-300
