#!/bin/bash
# d12 (class 1, indentation restart with an #include added at the end of indenterProperties): (a) the included file sets radius 22.5e-6 (the same value): accepted; (b) radius 22.4e-6: refused naming radius and the included file.
. "$(dirname "$0")/../lib.sh"
ik; echo "radius 22.5e-6;" > constant/inc; echo "#include \"inc\"" >> constant/indenterProperties
tryt 200 "(a) same radius in an include" cellIndentationFoam; cont; after
cd $W; rm -rf ind; ik; echo "radius 22.4e-6;" > constant/inc; echo "#include \"inc\"" >> constant/indenterProperties
tryt 200 "(b) radius 22.4e-6 in an include" cellIndentationFoam; cont; after
