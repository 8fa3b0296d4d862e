#!/bin/bash
# d47 (class 5, the commit marker of the latest time removed: the finished preview, rm 2e-09/.writeCommitted, restart latestTime): 2e-09 moved aside as uncommitted and the run continues from 1e-09 saying so (solid.h5 cut to 1e-09), or a refusal naming 2e-09; never a continuation from an unchecked 2e-09 without a word.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm 2e-09/.writeCommitted; tryt 240 "restart, 2e-09 unmarked" cellBlastFoam; cont; grep -a -i -m3 "aside\|uncommitted\|interrupted\|2e-09" $W/try.log | cut -c1-200; after
