#!/bin/bash
# f77 (class 2, calibrateCell's scratch folder inside the case): calibrateCell -work . (the case itself), -work constant, -work system: each refused before anything is written (the folder is not empty and not one calibrateCell marked as its own), naming -work; the case unchanged, nothing removed.
. "$(dirname "$0")/../lib.sh"
cal; sums > ../s0
for w in . constant system; do tryt 90 "-work $w" calibrateCell -work $w; killIn $W/cal; echo "   changed: $(changed ../s0)"; ls $w | head -5 | tr '\n' ' '; echo; done
