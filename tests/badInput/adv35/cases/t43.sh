#!/bin/bash
# t43: solidToFoam -region polyMesh / uniform / constant on a finished blast case: the fluid's committed time directories must not change
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
for r in polyMesh uniform constant system; do solidToFoam -region $r solid/solid.h5 > log.s.$r 2>&1; echo "-region $r: rc=$? $(grep -A1 FATAL log.s.$r | tail -1 | cut -c1-150)"; done
sums | grep -v "log\." > ../after; grep -v "log\." ../before | diff - ../after | grep "^[<>]" | head -8
setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; cellBlastFoam > log.run 2>&1; echo "restart rc=$?"; grep -A3 FATAL log.run | head -4
