#!/bin/bash
# f03 (class 1/5, blast restart, a log of another run): A's postProcessing/fsi/0/coupling.dat replaced by B's (bd2: same times, other values, a valid file), restart to 3e-9: refused naming the log (the commit recorded A's bytes), nothing written.
. "$(dirname "$0")/../lib.sh"
bd2; bd; rs; cp $W/blast2/postProcessing/fsi/0/coupling.dat postProcessing/fsi/0/coupling.dat; cmp -s coupling.dat $W/blast2/postProcessing/fsi/0/coupling.dat; sums > ../s0
tryt 240 "coupling.dat of B" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
