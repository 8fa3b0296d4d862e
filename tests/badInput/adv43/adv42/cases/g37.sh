#!/bin/bash
# g37 (class 2, g36 in rhoRiemannFoam): waterPulseWall (probes) run to 8e-8 s (writes every 2e-8); once 2e-08 is committed the user writes notes.txt into postProcessing/probes/0/ while the run goes on; then -overwrite (startFrom startTime): refused naming it, or recorded as a log and removed?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; sed -i "s/^startFrom .*/startFrom startTime;/" system/controlDict
rhoRiemannFoam > log.first 2>&1 & p=$!; waitFor 60 test -f 2e-08/.writeCommitted; printf 'g37 notes during the run\n' > postProcessing/probes/0/notes.txt; wait $p; echo "   run rc $?: times $(ls -d [1-9]* | tr '\n' ' '); markers naming notes.txt: $(grep -a -l 'notes.txt' */.writeCommitted 2>/dev/null | tr '\n' ' ')"
tryf "-overwrite" rhoRiemannFoam -overwrite; kept "g37 notes during the run"
