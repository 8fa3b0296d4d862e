#!/bin/bash
# g51 (class 4, solidToFoam's options at their edges) on the finished preview (bd): -wedgeAngle 0, -5, 360, 361, 1e-300, nan, 180.00000000000003, 5x; -region "", ../escape, a/b, constant, solid twice (-region solid -region fluid): each refused naming the option, the value and the valid range or form; nothing written outside the case (no $W/escape).
. "$(dirname "$0")/../lib.sh"
bd; for o in "0" "-5" "360" "361" "1e-300" "nan" "180.00000000000003" "5x"; do tryt 60 "-wedgeAngle $o" solidToFoam -wedgeAngle "$o" solid/solid.h5; done
for r in "" "../escape" "a/b" "constant"; do tryt 60 "-region '$r'" solidToFoam -region "$r" solid/solid.h5; done
tryt 60 "-region given twice" solidToFoam -region solid -region fluid solid/solid.h5; ls -d $W/escape constant/a constant/fluid 2>&1 | cut -c1-150
