#!/bin/bash
# z21: 2 ranks run to 2 ns; a power loss on ONE node: processor1/2e-09/.writeCommitted all NUL bytes (its size kept); mpirun -np 2 restart to 3 ns: both ranks go back to 1e-09 (said), or refused naming it, never continued from 2e-09 on one rank only? the ranks' times and solid.h5 steps agree after
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; nul processor1/2e-09/.writeCommitted
run 120 mpirun -np 2 cellBlastFoam -parallel > log.r 2>&1; fatal log.r 4; grep -a -i -m3 "incomplete\|aside\|writeGuard" log.r | cut -c1-220
echo "processor0: $(ls -da processor0/[1-9]* | tr '\n' ' '); processor1: $(ls -da processor1/[1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5), xmf $(xmfsteps solid/solid.xmf)"
