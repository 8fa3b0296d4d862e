#!/bin/bash
# w90: blast: the 0/ directory removed after a run to 2 ns (a user cleaning up), restart from 2 ns: continues, or a clear error?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; rm -rf 0; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r
