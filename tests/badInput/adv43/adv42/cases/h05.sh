#!/bin/bash
# h05 (phase C, q17's shapes in rhoRiemannFoam and on 2 ranks): (a) waterPulseWall (rhoRiemannFoam, probes) SIGKILLed before its first commit, the user's notes.md ("# ...") in postProcessing/probes/0/, -overwrite; (b) a 2-rank blast SIGKILLed before its first commit, notes.md ("# ...") in postProcessing/solidProbes/0/, 2-rank -overwrite: kept or refused?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
rhoRiemannFoam > log.k 2>&1 & p=$!; waitFor 60 bash -c 'ls postProcessing/probes/0/* > /dev/null 2>&1'; sleep 0.2; kill -KILL $p; wait $p 2>/dev/null; echo "   (a) killed: times $(ls -d [0-9]* | tr '\n' ' '); probes/0: $(ls postProcessing/probes/0 | tr '\n' ' ')"
sed -i "s/^startFrom .*/startFrom startTime;/" system/controlDict; printf "# My analysis h05a\n" > postProcessing/probes/0/notes.md; tryf "(a) rhoRiemannFoam -overwrite" rhoRiemannFoam -overwrite; kept "My analysis h05a"
cd $W; pblast; blastEnd 8e-9 4e-9; mpirun -np 2 cellBlastFoam -parallel > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.3; pkill -KILL -P $p; kill -KILL $p; wait $p 2>/dev/null; killIn $W/blast; sleep 0.5; echo "   (b) killed: processor0 $(ls processor0 | tr '\n' ' ')"
blastEnd 2e-9 1e-9; printf '# My analysis h05b\n' > postProcessing/solidProbes/0/notes.md; tryf "(b) 2-rank -overwrite" mpirun -np 2 cellBlastFoam -parallel -overwrite; kept "My analysis h05b"
