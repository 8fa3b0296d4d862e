#!/bin/bash
# f71 (class 6, cellIndentationFoam's factorisation estimate at its limit): the smoke indentation with maxFactorMemory 1 (refused naming the estimate E in B), then maxFactorMemory E as printed (accepted: the run starts; stopped after 30 s) and E x (1 - 1e-3) (refused).
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../ip0; echo "maxFactorMemory 1;" >> constant/indenterProperties; tryt 60 "maxFactorMemory 1" cellIndentationFoam
E=$(grep -a -o '[0-9.]\+e[+-]\?[0-9]\+ B\|[0-9.]\+ B' $W/try.log | head -1 | grep -o '^[0-9.e+-]\+'); echo "   E=$E"
for m in $E $(/usr/bin/python3 -c "print(repr(float('$E') * (1 - 1e-3)))"); do cp ../ip0 constant/indenterProperties; echo "maxFactorMemory $m;" >> constant/indenterProperties; rm -rf postProcessing; tryt 30 "maxFactorMemory $m" cellIndentationFoam; done
