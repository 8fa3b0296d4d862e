#!/bin/bash
# f19 (class 1, reconstructPar over a parallel run, then continued serially and in parallel): q reconstructed (reconstructPar), then (S) a serial restart to 3e-9 and (P) the parallel restart to 3e-9 of a copy: both rc 0, and S equals P to the project's parallel bound (1e-10 of each probe's range; closeTo) - a reconstructed time continued serially must be the same physics.
. "$(dirname "$0")/../lib.sh"
q; tryt 120 "reconstructPar" reconstructPar; ls -d [0-9]* | tr '\n' ' '; echo; cp -a $W/q $W/P
latest; qEnd 3e-9; tryt 280 "(S) serial restart of the reconstructed case" cellBlastFoam; cont
cd $W/P; latest; qEnd 3e-9; tryt 280 "(P) parallel restart" mpirun -np 2 cellBlastFoam -parallel; cont
cd $W/q; closeTo $W/P
