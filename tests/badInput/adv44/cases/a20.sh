#!/bin/bash
# a20 (class 1, cellIndentationFoam, an input #included through an ENVIRONMENT VARIABLE outside the case): the smoke indentation's loading table (protocol) and radius moved to "$ADV44IND/bead" (#include in constant/indenterProperties; ADV44IND exported, outside the case); killed after its first checkpoint; (a) the radius 22.5 -> 20 um in that file, restart: refused naming the entry? (b) restored: continues?
. "$(dirname "$0")/../lib.sh"
export ADV44IND=$W/shared; mkdir -p $ADV44IND; ind; f=constant/indenterProperties; grep -a '^ *radius' $f > $ADV44IND/bead; sed -i 's|^ *radius .*|#include "$ADV44IND/bead"|' $f; grep -a -c 'ADV44IND' $f; cd $W; rm -rf ind
indKilled 0.3 > /dev/null; echo "   killed: $(ls postProcessing/indentation | tr '\n' ' ')"; grep -a -c 'ADV44IND' constant/indenterProperties
cp $ADV44IND/bead ../bead.orig; sed -i 's/22.5e-6/20e-6/' $ADV44IND/bead; sums > ../s; tryf "(a) radius 20 um in \$ADV44IND/bead, restart" cellIndentationFoam; nochange ../s
cp ../bead.orig $ADV44IND/bead; tryf "(b) restored, restart" cellIndentationFoam; forceOk postProcessing/indentation/force.dat
