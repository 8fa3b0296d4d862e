#!/bin/bash
# w78: indentation protocol rows at the edges: two rows with the same label A, a negative rate, a depth 1e-3 m (1 mm into a 7.9 um cell), a stage kind 'Load', a hold of duration 0
. "$(dirname "$0")/../lib.sh"
ind; f=constant/indenterProperties; cp $f ../ip
sed -i 's/    (B   hold    0       1)/    (A   hold    0       1)/' $f; try "label A twice" cellIndentationFoam
cp ../ip $f; sed -i 's/    (A   load    0.3e-6  0.3e-6)/    (A   load    0.3e-6  -0.3e-6)/' $f; try "negative rate" cellIndentationFoam
cp ../ip $f; sed -i 's/    (A   load    0.3e-6  0.3e-6)/    (A   load    0.3e-6  1e-3)/' $f; try "depth 1 mm" cellIndentationFoam
cp ../ip $f; sed -i 's/    (A   load    0.3e-6  0.3e-6)/    (A   Load    0.3e-6  0.3e-6)/' $f; try "kind Load" cellIndentationFoam
cp ../ip $f; sed -i 's/    (B   hold    0       1)/    (B   hold    0       0)/' $f; try "hold 0 s" cellIndentationFoam
echo "-- depth 1 mm in full:"; cp ../ip $f; sed -i 's/    (A   load    0.3e-6  0.3e-6)/    (A   load    0.3e-6  1e-3)/' $f; cellIndentationFoam > log.d 2>&1; echo "rc=$?"; grep -a -A1 "FATAL" log.d | cut -c1-250
