#!/bin/bash
# d13 (class 1, indentation restart after the first (already run) protocol row rewritten): (a) rate 0.3e-6 written 3e-7 and 0.30e-6 (the same numbers): accepted (refusal UNCLEAR low); (b) 0.30000001e-6: refused naming the row.
. "$(dirname "$0")/../lib.sh"
ik; grep -n "(A " constant/indenterProperties
sed -i "s/(A *load *0.3e-6 *0.3e-6)/(A load 3e-7 0.30e-6)/" constant/indenterProperties; grep "(A " constant/indenterProperties
tryt 200 "(a) same numbers, other spelling" cellIndentationFoam; cont; after
cd $W; rm -rf ind; ik; sed -i "s/(A *load *0.3e-6 *0.3e-6)/(A load 0.30000001e-6 0.3e-6)/" constant/indenterProperties; grep "(A " constant/indenterProperties
tryt 200 "(b) rate 0.30000001e-6" cellIndentationFoam; cont; after
