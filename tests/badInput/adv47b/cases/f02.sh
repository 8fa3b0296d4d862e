#!/bin/bash
# f02 (class 1, blast restart, the solid results of another run): A's solid/solid.h5 and solid.xmf replaced by those of B (bd2, pulse doubled, same steps), restart to 3e-9: refused naming solid/solid.h5 (another run's), nothing written.
. "$(dirname "$0")/../lib.sh"
bd2; bd; rs; cp $W/blast2/solid/solid.h5 $W/blast2/solid/solid.xmf solid/; sums > ../s0
tryt 240 "A's solid.h5/.xmf replaced by B's" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
