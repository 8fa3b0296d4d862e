#!/bin/bash
# c12: cellBlastFoam running while the user runs foamListTimes/foamToVTK? -> solidToFoam on blast while running
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 1e-8
cellBlastFoam > log.a 2>&1 & p=$!; sleep 1.5; solidToFoam solid/solid.h5 > log.s 2>&1; echo "solidToFoam rc=$?"; grep -A3 "FATAL" log.s | head -4; wait $p; echo "run rc=$?"; tail -1 log.a
