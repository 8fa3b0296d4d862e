#!/bin/bash
# f06 (class 1/2, a results folder renamed: solid/ renamed solid.bak), restart latestTime to 3e-9: refused naming solid/solid.h5 (missing), nothing written; never a new solid.h5 beginning at 2e-09 beside the water's full history.
. "$(dirname "$0")/../lib.sh"
bd; rs; mv solid solid.bak; sums > ../s0
tryt 240 "solid/ renamed solid.bak" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls solid solid.bak 2>&1 | tr '\n' ' '; echo
