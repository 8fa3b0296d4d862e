#!/bin/bash
# k56 (class 4, the quarter's -np and -refineCell with -oGrid orthogonal): fresh quarter copies, -noRun, smoke sizes: -np 0, -np 1.0, -np 2.5, -np 99 (above nproc), -refineCell 0, -refineCell 5e-6 (above the default innerMargin 3.95e-6: the header's range (0, innerMargin]), and -refineCell 1e-6 -oGrid orthogonal (valid alone, together?). Expected: the invalid ones refused naming the option and range before anything is written; the last one prepares a case whose checkMesh is OK, or is refused naming both options.
. "$(dirname "$0")/../lib.sh"
S="-box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -noRun -noPlots"
for o in "-np 0" "-np 1.0" "-np 2.5" "-np 99" "-refineCell 0" "-refineCell 5e-6" "-refineCell 1e-6 -oGrid orthogonal"; do rm -rf $W/qa; cp -r "$ROOT/tutorials/blast/quarter3D" $W/qa; cd $W/qa; sums > ../s0
  tryt 500 "Allrun $o" ./Allrun $S $o; echo "   changed: $(changed ../s0 | cut -c1-160)"; [ -f log.checkMesh ] && echo "   checkMesh: $(grep -a -m2 'Mesh OK\|Failed\|\*\*\*' log.checkMesh | tr '\n' ' ' | cut -c1-160)"; cd $W; done
