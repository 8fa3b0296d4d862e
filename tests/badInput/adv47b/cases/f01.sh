#!/bin/bash
# f01 (class 1, blast restart, a time directory copied from another run): case A (bd, finished to 2e-09) gets the 2e-09 of case B (bd2: the same case files but 0/p's pulse doubled, run to 2e-09), then restarts (latestTime, to 3e-9): refused naming the time (its solid state / record not A's run), nothing written; never "Continuing" with A's solid.h5 and B's water.
. "$(dirname "$0")/../lib.sh"
bd2; bd; rs; rm -rf 2e-09; cp -a $W/blast2/2e-09 .; sums > ../s0
tryt 240 "A's 2e-09 replaced by B's (pulse x2)" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
