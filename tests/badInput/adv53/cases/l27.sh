#!/bin/bash
# CASETIMEOUT=600
# l27 (new, class 5: a valid result file of another run under this case's name - a copy between two similar cases,
# parse-valid and checksummed, but not this run's): bd (pulse 50 MPa) and bd2 (the same case files, pulse x2), both to
# 2e-9: bd's solid/solid.h5 and solid.xmf replaced by bd2's, then (a) solidToFoam (writes <time>/solid fields for
# foamToVTK), (b) the restart to 3e-9; (c) bd's postProcessing/solidProbes replaced by bd2's: planeWave -check.
# Expected: refused naming the file as another run's (the commit markers record the run), nothing written; bd2's solid
# fields written into bd's times rc 0 = SILENT; (b) refused (adv52 p03: refused).
. "$(dirname "$0")/../lib.sh"
bd2; B2=$PWD; cd $W; bd; rm -f .runLock; cp $B2/solid/solid.h5 $B2/solid/solid.xmf solid/; sums > $W/s0
tryt 120 "(a) solidToFoam on bd2's solid.h5 in bd" solidToFoam solid/solid.h5; echo "   said: $(say 2 | cut -c1-250) | wrote: $(changed $W/s0 | cut -c1-200)"
rm -rf constant/solid [0-9]*/solid; rs; tryt 300 "(b) the restart to 3e-9 with bd2's solid.h5" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; rm -rf blast; bd; rm -f .runLock; rm -rf postProcessing/solidProbes; cp -a $B2/postProcessing/solidProbes postProcessing/
tryt 300 "(c) planeWave -check with bd2's solidProbes logs" planeWave -case . -check; echo "   said: $(say 2 | cut -c1-250) | last: $(grep -a -v '^ *$' $W/try.log | tail -2 | tr '\n' '|' | cut -c1-250)"
