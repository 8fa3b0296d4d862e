#!/bin/bash
# x35: blast case copied with dot files left out (tar --exclude='*/.*', as rsync --exclude='.*': every .writeCommitted gone, the logs whole), restart to 3 ns: refused with -acceptEdited named; with -acceptEdited: continued from 2e-09, and the result equal to the continued original?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cd ..; mkdir nodot; (cd blast && tar cf - --exclude='*/.*' .) | (cd nodot && tar xf -); find nodot -name '.*' | head -3; cd nodot; try "no markers" cellBlastFoam; run 120 cellBlastFoam -acceptEdited > log.acc 2>&1; tail -1 log.acc; fatal log.acc 3
cd ../blast; cellBlastFoam > log.r 2>&1; cmp 3e-09/p ../nodot/3e-09/p && echo "3e-09/p equal"
