#!/bin/bash
# CASETIMEOUT=600
# l24 (new, class 2/5: a user's clean-up between run and restart - the probe logs or the solid's HDF5 results removed,
# "they are big"): bd restarted to 3e-9 after (a) postProcessing/fluidProbes removed, (b) postProcessing/ removed whole,
# (c) solid/solid.h5 and solid.xmf removed; then planeWave -check / solidToFoam on the result. Expected: refused naming
# what is missing (the markers hold their digests), or the restart said, and the later tools say the history is partial;
# a run rc 0 whose logs start at 2e-09 with planeWave measuring them as the run = SILENT (low).
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cd $W; cp -a blast b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 300 "$1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"; }
back; rm -rf postProcessing/fluidProbes; one "(a) postProcessing/fluidProbes removed"
back; rm -rf postProcessing; one "(b) postProcessing/ removed"
back; rm -f solid/solid.h5 solid/solid.xmf; one "(c) solid/solid.h5 and .xmf removed"; tryt 120 "(c2) solidToFoam after it" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-200)"
