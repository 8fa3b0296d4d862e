#!/bin/bash
# w30: blast: 2e-09/uniform/solidState replaced by the 1e-09 one (an older version of the same file), restart: refused naming the file?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp 1e-09/uniform/solidState 2e-09/uniform/solidState
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
