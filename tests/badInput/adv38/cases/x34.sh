#!/bin/bash
# x34: blast finished to 2 ns: the latest time holds BOTH markers (.writeInProgress beside .writeCommitted: a copy back from a backup that had the in-progress one), restart: what does it do and say?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; touch 2e-09/.writeInProgress; try "both markers" cellBlastFoam; ls -d [1-9]* | tr '\n' ' '
