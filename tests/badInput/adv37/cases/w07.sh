#!/bin/bash
# w07: blast: a case decomposed for 2 ranks run with mpirun -np 3 (and -np 1 -parallel): refused with a message naming the decomposition?
. "$(dirname "$0")/../lib.sh"
pblast; run 60 mpirun -np 3 cellBlastFoam -parallel > log.3 2>&1; fatal log.3 8; echo "--"; run 60 mpirun -np 1 cellBlastFoam -parallel > log.1 2>&1; fatal log.1 8; ls -a | tr '\n' ' '
