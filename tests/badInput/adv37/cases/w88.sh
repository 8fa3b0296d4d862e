#!/bin/bash
# w88: blast: after a run to 2 ns, blockMesh re-run (the same mesh, new file times) and every input touched: the restart accepted (content unchanged), not refused?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; blockMesh > log.bm2 2>&1; echo "blockMesh rc=$?"; find constant system -type f -exec touch {} +
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 6; tail -1 log.r
