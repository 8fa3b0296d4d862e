#!/bin/bash
# x31: blast finished to 2 ns, the case copied the way users copy: cp -r (times and modes not kept), cp -a, tar c|x; each copy restarted to 3 ns: accepted (contents unchanged)?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cd ..
cp -r blast c1; (cd c1 && try "cp -r" cellBlastFoam); cp -a blast c2; (cd c2 && try "cp -a" cellBlastFoam); mkdir c3; (cd blast && tar cf - .) | (cd c3 && tar xf -); (cd c3 && try "tar" cellBlastFoam)
