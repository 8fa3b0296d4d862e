#!/bin/bash
# k31: blast: solid.h5 of the same run restored from an earlier copy (taken at 1 ns), restart latestTime from 2 ns
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 1e-9; cellBlastFoam > log.1 2>&1; cp solid/solid.h5 ../solid1ns.h5; cp solid/solid.xmf ../solid1ns.xmf
setd system/controlDict startFrom latestTime; setd system/controlDict endTime 2e-9; cellBlastFoam > log.2 2>&1; echo "continued rc=$?"
cp ../solid1ns.h5 solid/solid.h5; cp ../solid1ns.xmf solid/solid.xmf; setd system/controlDict endTime 3e-9
cellBlastFoam > log.run 2>&1; rc=$?; grep -A4 "FATAL" log.run | head -5; grep "Solid: restarted" log.run; echo "rc=$rc"
