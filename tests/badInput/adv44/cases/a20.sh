#!/bin/bash
# a20 (class 1, cellIndentationFoam, an input #included through an ENVIRONMENT VARIABLE outside the case): the smoke indentation's radius moved to "$ADV44IND/bead" (#include in constant/indenterProperties; ADV44IND exported, outside the case), 10x finer depth steps; killed 0.3 s after its first checkpoint; (a) the radius 22.5 -> 20 um in that file, restart: refused naming the entry? (b) restored: continues, force.dat whole?
. "$(dirname "$0")/../lib.sh"
export ADV44IND=$W/shared; mkdir -p $ADV44IND; ind; f=constant/indenterProperties; grep -a '^ *radius' $f > $ADV44IND/bead; sed -i 's|^ *radius .*|#include "$ADV44IND/bead"|' $f; echo "   includes: $(grep -a 'ADV44IND' $f)"
sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' $f; cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/restart.h5; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; latest
echo "   killed: $(ls postProcessing/indentation | tr '\n' ' '); force rows $(grep -vc '^#' postProcessing/indentation/force.dat); the run read: $(grep -a -m1 'Indenter: radius' log.first | cut -c1-60)"
cp $ADV44IND/bead ../bead.orig; sed -i 's/22.5e-6/20e-6/' $ADV44IND/bead; sums > ../s; tryf "(a) radius 20 um in \$ADV44IND/bead, restart" cellIndentationFoam; nochange ../s; grep -a -m1 'Indenter: radius' $W/try.log | cut -c1-60
cp ../bead.orig $ADV44IND/bead; tryf "(b) restored, restart" cellIndentationFoam; forceOk postProcessing/indentation/force.dat
