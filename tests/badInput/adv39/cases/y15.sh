#!/bin/bash
# y15: integer entries in other spellings (fix19t: exponent/decimal refused with the range): solidSubcycles +2, 02, 2.0, 0x2, 2e0, " 2 " (spaces), 3000: each accepted, or refused with the range
. "$(dirname "$0")/../lib.sh"
blast; each constant/fsiProperties "solidSubcycles +2" "solidSubcycles 02" "solidSubcycles 2.0" "solidSubcycles 0x2" "solidSubcycles 2e0" "solidSubcycles 3000" -- cellBlastFoam
