#!/bin/bash
# w11: blast: a second 2-rank run started in the case while a first 2-rank run is running: refused naming the first? the first ends well?
. "$(dirname "$0")/../lib.sh"
pblast; blastEnd 8e-9 1e-9; mpirun -np 2 cellBlastFoam -parallel > log.a 2>&1 & p=$!; sleep 1.2
run 60 mpirun -np 2 cellBlastFoam -parallel > log.b 2>&1; fatal log.b 6; wait $p; echo "first rc=$?"; tail -1 log.a; ls -a . | tr '\n' ' '
