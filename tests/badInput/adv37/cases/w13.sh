#!/bin/bash
# w13: blast: decomposePar -force run while the 2-rank solver runs in the case (an OpenFOAM utility at once): what happens to the running case?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 8e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.a 2>&1 & p=$!; sleep 1.2
run 60 decomposePar -force > log.dec 2>&1; tail -3 log.dec; wait $p; echo "parallel rc=$?"; tail -2 log.a; ls processor0 | tr '\n' ' '
