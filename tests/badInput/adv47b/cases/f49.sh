#!/bin/bash
# f49 (class 4, the 3D quarter Allrun's option edges, -noRun): -np 3 on a 2-core machine (refused: at most nproc), -np 2.0, -topRounding 100 (the bound: accepted), 100.00000000000001 (refused naming [5, 100]), -topRounding 4.999999999999999 (refused), -refineCell 0 (refused: (0, innerMargin]). Accepted ones stopped after 25 s and cleaned.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/blast/quarter3D $W/q3; cd $W/q3
for o in "-np 3" "-np 2.0" "-topRounding 100" "-topRounding 100.00000000000001" "-topRounding 4.999999999999999" "-refineCell 0"; do
  tryt 25 "$o" ./Allrun -box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -noPlots -noRun $o; [ -f .allrunOptions ] && echo "   (accepted: .allrunOptions written)"; killIn $W/q3; ./Allclean > /dev/null 2>&1; done
