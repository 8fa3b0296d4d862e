#!/bin/bash
# w12: blast: a serial cellBlastFoam started in a case while a 2-rank run is running in it: refused? the parallel run ends well?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 8e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.a 2>&1 & p=$!; sleep 1.2
run 60 cellBlastFoam -overwrite > log.b 2>&1; fatal log.b 6; wait $p; echo "parallel rc=$?"; tail -1 log.a
