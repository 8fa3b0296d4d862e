#!/bin/bash
# d10 (class 1, indentation restart after solidProperties fixed edited): (a) the same three constraints in another order: accepted (a refusal is UNCLEAR low); (b) (fixedBottom 1) removed: refused naming fixed.
. "$(dirname "$0")/../lib.sh"
ik; cp constant/solidProperties ../sp
sed -i "s/(fixedBottom 0) (fixedBottom 1)     \/\/ slipless substrate/(axis 0) (fixedBottom 1)/; s/^    (axis 0)                            \/\/ u_r = 0 on the axis/    (fixedBottom 0)/" constant/solidProperties; grep -A3 "^fixed" constant/solidProperties | tr "\n" " "; echo
tryt 200 "(a) reordered" cellIndentationFoam; cont; after
cd $W; rm -rf ind; ik; sed -i "s/(fixedBottom 0) (fixedBottom 1)/(fixedBottom 0)/" constant/solidProperties; grep -A3 "^fixed" constant/solidProperties | tr "\n" " "; echo
tryt 200 "(b) fixedBottom 1 removed" cellIndentationFoam; cont; after
