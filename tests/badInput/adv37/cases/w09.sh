#!/bin/bash
# w09: blast 2 ranks run to 2 ns: 64 zero bytes inside processor1/2e-09/rhoE, restart on 2 ranks: refused naming the file?
. "$(dirname "$0")/../lib.sh"
pblastDone; dd if=/dev/zero of=processor1/2e-09/rhoE bs=1 seek=1500 count=64 conv=notrunc 2>/dev/null; latest; blastEnd 3e-9 1e-9
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 8; tail -1 log.r
