#!/bin/bash
# i23 (class 5/HANG, the restart-state check failing on one rank): pbd (2 ranks, 2e-09 on both) with processor1's 2e-09/rho
# cell 3 = -1 (then NaN, then rhoE -1e12 in processor0 only), restarted with -acceptEdited on 2 ranks to 3e-9: every rank
# stops at once naming the rank, cell, centre and field; exit non-zero within seconds, never a hang (300 s KILL) and no
# SIGABRT/sigFpe trace.
. "$(dirname "$0")/../lib.sh"
pbd; rs; cd $W; mv pblast b0
one() { rm -rf $W/pblast; cp -a $W/b0 $W/pblast; cd $W/pblast; }
one; fset processor1/2e-09/rho internal 3 -1; s=$(date +%s); tryt 300 "processor1 rho -1" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; echo "   $(( $(date +%s) - s )) s"
one; fset processor1/2e-09/rho internal 3 nan; s=$(date +%s); tryt 300 "processor1 rho nan" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; echo "   $(( $(date +%s) - s )) s"
one; fset processor0/2e-09/rhoE internal 3 -1e12; s=$(date +%s); tryt 300 "processor0 rhoE -1e12" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; echo "   $(( $(date +%s) - s )) s"
