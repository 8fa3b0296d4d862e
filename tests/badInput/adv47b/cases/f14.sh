#!/bin/bash
# f14 (class 2/3, decomposePar over a running serial case, then a parallel start): the serial preview restarted to 5e-9 runs; beside it the case is split for 2 ranks and decomposePar -force run (processor*/0 only). After the serial run ends, mpirun -np 2 cellBlastFoam -parallel (startFrom latestTime: the ranks hold only 0): refused (a new start over the serial results 1e-09..5e-09, solid.h5, logs), nothing changed.
. "$(dirname "$0")/../lib.sh"
bd; blastEnd 5e-9 1e-9; latest; cellBlastFoam > log.bg 2>&1 & p=$!; waitFor 60 test -d 3e-09
splitY 4e-6 > ../split.log 2>&1; tryt 120 "decomposePar -force during the run" decomposePar -force; ls -d processor*/* | tr '\n' ' '; echo
wait $p; echo "   serial run rc=$?"; after; sums > ../s0
tryt 240 "parallel start over the serial results" mpirun -np 2 cellBlastFoam -parallel; cont; echo "   changed: $(changed ../s0)"; after
