#!/bin/bash
# f53 (class 5, a commit marker of another time): the preview's 2e-09/.writeCommitted replaced by 1e-09's (a whole, sealed marker of another time), restart latestTime: 2e-09 not taken as committed (moved aside, continued from 1e-09) or refused naming the marker; never continued from 2e-09 with its files unverified.
. "$(dirname "$0")/../lib.sh"
bd; rs; cp 1e-09/.writeCommitted 2e-09/.writeCommitted; sums > ../s0
tryt 240 "2e-09 with 1e-09's marker" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after; ls -d .*incomplete* *incomplete* 2>/dev/null
