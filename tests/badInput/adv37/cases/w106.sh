#!/bin/bash
# w106: solidProperties interfaceProbe and interfaces at the edges: heightFraction 1.5, heightFraction 0, regions (cytoplasm cytoplasm), side middle, interfaces ((membrane membrane))
. "$(dirname "$0")/../lib.sh"
blast; f=constant/solidProperties; cp $f ../sp
for e in "heightFraction 1.5" "heightFraction 0" "side middle"; do cp ../sp $f; k=${e%% *}; sed -i "0,/^\( *\)$k .*/s//\1$e;/" $f; try "$e" cellBlastFoam; rm -rf solid postProcessing [1-9]*; done
cp ../sp $f; sed -i 's/regions         (cytoplasm nucleus);/regions (cytoplasm cytoplasm);/' $f; try "regions (cytoplasm cytoplasm)" cellBlastFoam; rm -rf solid postProcessing [1-9]*
cp ../sp $f; sed -i 's/^interfaces      ((membrane cytoplasm) (cytoplasm nucleus));/interfaces ((membrane membrane));/' $f; grep -n "^interfaces" $f; try "interfaces ((membrane membrane))" cellBlastFoam
