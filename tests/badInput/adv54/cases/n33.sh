#!/bin/bash
# CASETIMEOUT=900
# n33 (new, class 5/2: the ordinary parallel workflow's clean-up against the logs' digests, which the commit markers of the
# time folders hold): (a) pbd (2 ranks, finished at 2e-9): reconstructPar, then the processor*/ folders removed (to save
# space, as users do): planeWave -case . -check and incidentWindow.py; (b) bd (serial, finished) decomposed afterwards
# (decomposePar -latestTime... and the serial time folders but 0 removed, to go on in parallel): planeWave -case .;
# (c) pbd reconstructed, processor*/ kept: planeWave. Expected: the case's own logs measured in each (their markers are
# still somewhere the reader looks, or the clean-up keeps them); refused as "made or changed by hand" = UNCLEAR (a false
# accusation that blocks every measure of an ordinary run; the user must give -acceptHandMade, which then also takes
# real edits).
. "$(dirname "$0")/../lib.sh"
pbd; cp -a . $W/p0; tryt 300 "(0) reconstructPar" reconstructPar; echo "   times: $(ls -d [0-9]* | tr '\n' ' ') | markers at the case level: $(ls -d [0-9]*/.writeCommitted 2>/dev/null | tr '\n' ' ')"
tryt 300 "(c) planeWave, processor*/ kept" planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"
rm -rf processor*; tryt 300 "(a) planeWave after processor*/ removed" planeWave -case .; echo "   said: $(say 2 | cut -c1-300)"
iw .; echo "   (a) incidentWindow: $(grep -a -v '^ *$' $W/try.log | tail -n 1 | cut -c1-250)"
cd $W; bd; printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (1 2 1); delta 0.001; }\n' > system/decomposeParDict
tryt 300 "(b0) decomposePar -latestTime" decomposePar -latestTime; echo "   processor0: $(ls -A processor0 | tr '\n' ' ') | markers: $(ls -d processor0/*/.writeCommitted 2>/dev/null | tr '\n' ' ')"
rm -rf 1e-09 2e-09; tryt 300 "(b) planeWave after the serial times removed" planeWave -case .; echo "   said: $(say 2 | cut -c1-300)"
