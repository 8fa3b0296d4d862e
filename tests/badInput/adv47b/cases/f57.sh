#!/bin/bash
# f57 (class 2, a case copied with hard links, cp -al, as snapshot tools do): the copy restarted to 3e-9; the original's files (solid.h5, solid.xmf, the logs, times) must be unchanged (the writer replaces files, or says it shares them); a changed original is an original whose times stop at 2e-09 with a solid.h5 of 3 steps.
. "$(dirname "$0")/../lib.sh"
bd; cd $W; cp -al blast copy; cd blast; sums > ../s0; cd ../copy; rs
tryt 240 "restart of the hard-linked copy" cellBlastFoam; cont; after; cd ../blast; echo "   original: $(nochange ../s0) | solid.h5 $(h5steps solid/solid.h5) steps, xmf $(xmfsteps solid/solid.xmf)"
