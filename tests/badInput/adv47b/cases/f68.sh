#!/bin/bash
# f68 (class 6, fluidWedgeMesh.py -maxCells at the exact count): the preview's wedge with the small sizes and -maxCells 1 (refused naming the count N), then -maxCells N (accepted: the mesh written) and N-1 (refused naming N and the limit).
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/wm; cd $W/wm; o="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -Z 20e-6"
tryt 60 "-maxCells 1" /usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py $o -maxCells 1 -o $W/wm/bm1; N=$(grep -a -o '[0-9]\+ cells' $W/try.log | grep -o '[0-9]\+' | head -1); echo "   N=$N"
for m in $N $((N - 1)); do tryt 60 "-maxCells $m" /usr/bin/python3 $ROOT/tutorials/blast/fluidWedgeMesh.py $o -maxCells $m -o $W/wm/bm$m; ls $W/wm | tr '\n' ' '; echo; done
