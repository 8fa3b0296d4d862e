#!/bin/bash
# z32: the verification case waterPulseWall (rhoRiemannFoam with a probes function object) run to 4e-08 s: (a) `rhoRiemannFoam -postProcess` over it: the probes log kept? a restart to 6e-08 then continues? (b) a user's notes.txt in postProcessing/probes/0/, then `rhoRiemannFoam -overwrite` from 0: the note kept?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
sed -i 's/^endTime .*/endTime 4e-8;/' system/controlDict; run 200 rhoRiemannFoam > log.first 2>&1 | tail -1; sums > ../before; ls postProcessing/*/0
tryf "(a) -postProcess" rhoRiemannFoam -postProcess; echo "   changed: $(changed ../before)"
sed -i 's/^endTime .*/endTime 6e-8;/' system/controlDict; tryf "(a) restart to 6e-8" rhoRiemannFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
echo "my notes about the probes" > postProcessing/probes/0/notes.txt; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict
tryf "(b) -overwrite" rhoRiemannFoam -overwrite; echo "   notes.txt: $(grep -rl 'my notes about the probes' . 2>/dev/null | tr '\n' ' ' || true)"; [ -n "$(grep -rl 'my notes about the probes' .)" ] || echo "   notes.txt GONE"
