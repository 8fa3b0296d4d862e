#!/bin/bash
# f63 (class 1, a serial run continued in parallel from a decomposed time without a commit marker): the preview run serially to 2e-09 (bd), split for 2 ranks and decomposePar -latestTime (processor*/2e-09, written by decomposePar, no marker), then mpirun -np 2 cellBlastFoam -parallel to 3e-9: either refused naming the unmarked time (and -acceptEdited) or continued; if continued, its logs equal the serial restart to 3e-9 (B) to the project's parallel bound (1e-10 of each range: closeTo).
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; rs; tryt 240 "B: serial restart to 3e-9" cellBlastFoam
bd; rs; splitY 4e-6 > ../split.log 2>&1; tryt 120 "decomposePar -latestTime" decomposePar -latestTime; ls -d processor0/* | tr '\n' ' '; echo
tryt 240 "(a) parallel restart from the decomposed 2e-09" mpirun -np 2 cellBlastFoam -parallel; cont
[ -d processor0/3e-09 ] || { tryt 240 "(b) the same with -acceptEdited" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; cont; }
closeTo $W/B
