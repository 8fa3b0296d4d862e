#!/bin/bash
# v04: sod (2000 cells, writes every 0.002 s): rhoRiemannFoam -overwrite SIGKILLed before its first write, then a restart: contents kept, advice
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/sodIdealGas" "$W/sod"; cd "$W/sod"; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; sed -i 's/^nCells .*/nCells 2000;/' system/blockMeshDict; sed -i 's/^writeInterval .*/writeInterval 0.002;/' system/controlDict
blockMesh > log.blockMesh 2>&1; setRiemannProblem > log.srp 2>&1; s=$(date +%s.%N); rhoRiemannFoam > log.first 2>&1; echo "first run rc=$? $(echo "$(date +%s.%N) - $s" | bc | cut -c1-4) s; times $(ls -d [0-9]* | tr '\n' ' ')"; contents > ../before
sed -i "s/^startFrom .*/startFrom startTime;/" system/controlDict; rhoRiemannFoam -overwrite > log.ow 2>&1 & p=$!; sleep 0.4; kill -KILL $p; wait $p 2>/dev/null; echo "lost after kill:"; lost ../before | wc -l; ls -a | tr '\n' ' '; echo
sed -i "s/^startFrom .*/startFrom latestTime;/" system/controlDict; rhoRiemannFoam > log.r1 2>&1; echo "restart rc=$?"; grep -a -A9 FATAL log.r1 | head -11 | cut -c1-300
