#!/bin/bash
# v28: blast: planeWave while cellBlastFoam runs (endTime 2e-8), with and without -partial
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 2e-8 1e-9; cellBlastFoam > log.a 2>&1 & p=$!; sleep 2.5
planeWave -dz 50e-9 > log.pw1 2>&1; echo "no -partial rc=$?"; grep -ai error log.pw1 | head -2 | cut -c1-250
planeWave -partial -dz 50e-9 > log.pw2 2>&1; echo "-partial rc=$?"; head -2 log.pw2 | cut -c1-250; grep -aci "error" log.pw2
wait $p; echo "solver rc=$?"
