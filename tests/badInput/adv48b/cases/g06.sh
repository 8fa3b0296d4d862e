#!/bin/bash
# g06 (class 1, the coupling state) bd with 2e-09/uniform/fsiState replaced by 1e-09/uniform/fsiState (a valid state of another time of the same run), restart latestTime to 3e-9: refused naming 2e-09/uniform/fsiState, nothing written.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp 1e-09/uniform/fsiState 2e-09/uniform/fsiState; sums > ../s0
tryt 240 "2e-09 fsiState of 1e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
