#!/bin/bash
# i21 (class 5, the restart state edited in the boundary only): bd's 2e-09 with the `value` list of rho's (then rhoE's) patch
# `interface` (the cell's wall) set to NaN, 0 and -1 in every face, the cells untouched; restart to 3e-9 (a) without
# -acceptEdited: refused (the field's digest), nothing changed; (b) with -acceptEdited: refused naming the field and patch,
# or run with the boundary values taken from the cells - then its logs equal the clean restart's (c) bitwise; never a
# floating-point exception, a NaN in a log or a result that differs from (c) without a word.
. "$(dirname "$0")/../lib.sh"
bd; rs; cd $W; mv blast b0; cp -a b0 ref; cd ref; tryt 300 "(c) clean restart" cellBlastFoam
one() { rm -rf $W/blast; cp -a $W/b0 $W/blast; cd $W/blast; }
for fv in "rho nan" "rho 0" "rho -1" "rhoE nan" "rhoE -1"; do set -- $fv
  one; fset 2e-09/$1 interface -1 $2 || continue; sums > ../s0; tryt 300 "(a) $1 interface = $2" cellBlastFoam; echo "   changed: $(changed ../s0)"
  tryt 300 "(b) $1 interface = $2, -acceptEdited" cellBlastFoam -acceptEdited; [ -d 3e-09 ] && cmpRef $W/ref; done
