#!/bin/bash
# g07 (class 1, the solid state) bd with 2e-09/uniform/solidState replaced by 1e-09/uniform/solidState, restart latestTime to 3e-9: refused naming 2e-09/uniform/solidState, nothing written; never the solid of 1 ns with the water of 2 ns.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp 1e-09/uniform/solidState 2e-09/uniform/solidState; sums > ../s0
tryt 240 "2e-09 solidState of 1e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
