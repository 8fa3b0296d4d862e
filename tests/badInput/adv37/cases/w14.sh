#!/bin/bash
# w14: blast: reconstructPar run repeatedly (-newTimes) while a 2-rank run writes (an OpenFOAM utility at once), then a serial restart from the root's latest reconstructed time: any reconstructed time incomplete, taken as good?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 8e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.a 2>&1 & p=$!
i=0; until [ "$(committed)" -ge 2 ] || [ $i -ge 300 ]; do sleep 0.1; i=$((i+1)); done
for k in 1 2 3 4 5 6; do reconstructPar -newTimes > log.rec$k 2>&1; echo -n "rec$k rc=$? "; sleep 0.3; done; echo; kill -0 $p 2>/dev/null && echo "the run was still running"; wait $p; echo "parallel rc=$?"
for t in $(ls -d [1-9]*); do echo "$t: $(ls $t | tr '\n' ' ') uniform: $(ls $t/uniform 2>/dev/null | tr '\n' ' ') marker: $(ls -a $t | grep -c writeCommitted)"; done
reconstructPar -latestTime > log.recL 2>&1; t=$(ls -d [1-9]* | sort -g | tail -1); echo "latest $t"; latest; blastEnd 9e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 5; tail -1 log.r
