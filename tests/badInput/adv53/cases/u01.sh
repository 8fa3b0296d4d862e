#!/bin/bash
# CASETIMEOUT=600
# u01 (fix19i row "a restart state file OpenFOAM cannot read, in parallel" (conservativeRestart), varied: another
# solver, another file, rank 0 instead of 1, an emptied file): waterPulseWall (rhoRiemannFoam) run to 2e-8 then restarted
# to 4e-8 after (a) serial: 2e-08/rhoU's first 8 bytes overwritten, (b) serial: 2e-08/rho emptied (0 bytes), (c) 2 ranks
# (decomposePar simple 2x1): processor0/2e-08/rho's header damaged, (d) 2 ranks: processor0/2e-08/rhoU removed (rank 0
# without one of the three); (e) the blast 2-rank base pbd: processor0/2e-09/rhoE's header damaged. Expected: each refused
# rc 1 naming the rank, the file(s) and the time; a restart from p, U, T without a word = SILENT; a signal = CRASH; an
# IOstream error naming no file = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
wp 2e-8; echo "   wp times: $(ls -d [0-9]* | tr '\n' ' ') | 2e-08 holds: $(ls 2e-08 | tr '\n' ' ')"; wpEnd 4e-8; cd $W; cp -a wp w0
again() { cd $W; rm -rf wp; cp -a w0 wp; cd wp; }
again; hdrDamage 2e-08/rhoU; tryt 200 "(a) serial, 2e-08/rhoU header damaged" rhoRiemannFoam; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(say 4 | cut -c1-350)"
again; hdrDamage 2e-08/rhoU; tryt 200 "(a2) serial, 2e-08/rhoU header damaged, -acceptEdited" rhoRiemannFoam -acceptEdited; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(say 4 | cut -c1-350)"
again; : > 2e-08/rho; tryt 200 "(b) serial, 2e-08/rho emptied" rhoRiemannFoam; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(say 4 | cut -c1-350)"
cd $W; rm -rf wp w0; wp 2e-8; rm -rf [1-9]* postProcessing .*overwritten*; wpEnd 2e-8; wpDec; tryt 300 "(0) 2 ranks to 2e-8" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) | processor0: $(ls processor0 | tr '\n' ' ') | holds $(ls processor0/2e-08 2>/dev/null | tr '\n' ' ')"
wpEnd 4e-8; cd $W; cp -a wp w0
again; hdrDamage processor0/2e-08/rho; tryt 200 "(c) 2 ranks, processor0/2e-08/rho header damaged" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(grep -a 'FATAL\|rank' $W/try.log | head -4 | tr -s ' ' | tr '\n' ' ' | cut -c1-450)"
again; hdrDamage processor0/2e-08/rho; tryt 200 "(c2) 2 ranks, processor0/2e-08/rho header damaged, -acceptEdited" mpirun -np 2 rhoRiemannFoam -parallel -acceptEdited; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(grep -a 'FATAL\|rank' $W/try.log | head -4 | tr -s ' ' | tr '\n' ' ' | cut -c1-450)"
again; : > processor1/2e-08/rhoE; tryt 200 "(c3) 2 ranks, processor1/2e-08/rhoE emptied, -acceptEdited" mpirun -np 2 rhoRiemannFoam -parallel -acceptEdited; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(grep -a 'FATAL\|rank' $W/try.log | head -4 | tr -s ' ' | tr '\n' ' ' | cut -c1-450)"
again; rm processor0/2e-08/rhoU; tryt 200 "(d) 2 ranks, processor0/2e-08/rhoU removed" mpirun -np 2 rhoRiemannFoam -parallel; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(grep -a 'FATAL\|rank' $W/try.log | head -4 | tr -s ' ' | tr '\n' ' ' | cut -c1-450)"
cd $W; rm -rf wp w0; pbd; rs; rm -f .runLock; hdrDamage processor0/2e-09/rhoE; tryt 300 "(e) blast 2 ranks, processor0/2e-09/rhoE header damaged, -acceptEdited" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; echo "   End $(grep -a -c '^End' $W/try.log) sig $(sig) | said: $(grep -a 'FATAL\|rank' $W/try.log | head -4 | tr -s ' ' | tr '\n' ' ' | cut -c1-450)"
