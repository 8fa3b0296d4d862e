#!/bin/bash
# w116: verification tutorial sodIdealGas (4000 cells): its Allrun SIGKILLed (with its solver) 1 s into rhoRiemannFoam, then the same ./Allrun: the solver re-run, or skipped (its log exists) and riemannError run on a partial result, exit 0?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/sodIdealGas" $W/c; cd $W/c; ./Allclean > /dev/null 2>&1; sed -i 's/^nCells  400;/nCells  4000;/' system/blockMeshDict
./Allrun > ../log.a1 2>&1 & p=$!; i=0; until [ -f log.rhoRiemannFoam ] || [ $i -ge 600 ]; do sleep 0.05; i=$((i+1)); done; sleep 1; kill -KILL $p; killIn $W/c; sleep 0.5
echo "killed: times $(ls -d 0.0* 2>/dev/null | tr '\n' ' '), log.rhoRiemannFoam last: $(tail -1 log.rhoRiemannFoam | cut -c1-60)"; run 200 ./Allrun > ../log.a2 2>&1; tail -1 ../log.a2; grep -a -i "already\|error\|refus" ../log.a2 | head -4 | cut -c1-200; echo "times now: $(ls -d 0.0* | tr '\n' ' ')"; ls postProcessing/riemannError 2>/dev/null
