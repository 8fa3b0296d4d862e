#!/bin/bash
# w91: blast: constant/cell.msh removed after a run to 2 ns, restart: refused naming the file?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; rm constant/cell.msh; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
