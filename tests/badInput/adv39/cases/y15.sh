#!/bin/bash
# y15: integer entries in other spellings (fix19t: exponent/decimal refused with the range): solidSubcycles +2, 02, 2.0, 0x2, 2e0, " 2 " (spaces), 3000: each accepted, or refused with the range; and the Allrun's -solidSubcycles 1000, 3000, 1e3 with -noRun (its range against fsiProperties' [1, 1000])
. "$(dirname "$0")/../lib.sh"
blast; each constant/fsiProperties "solidSubcycles +2" "solidSubcycles 02" "solidSubcycles 2.0" "solidSubcycles 0x2" "solidSubcycles 2e0" "solidSubcycles 3000" -- cellBlastFoam
cd $W; for v in 1000 3000 1e3; do prev; run 60 ./Allrun $PREV -endTime 2e-9 -solidSubcycles $v -noRun > ../log.n 2>&1; echo "Allrun -solidSubcycles $v -noRun: $(grep -a -i -m1 "error" ../log.n | cut -c1-200)"; cd $W; rm -rf $W/c; done
