#!/bin/bash
# CASETIMEOUT=900
# n23 (new, class 3/5: a case copied WHILE its run writes - a user's `cp -a` of a live case to try a variant - then both
# go on): the smoke indentation with 10x finer steps started; after 2 s (rows and a checkpoint written) `cp -a` of the
# case to B (its .runLock, a sidecar and force.dat as they were at that instant); A runs to its end; B: plotIndentation.py
# as copied, then cellIndentationFoam (startFrom latestTime) in B, then plotIndentation.py. Expected: B's copied lock
# seen as stale or A's (named); B's restart cuts what its checkpoint does not vouch for and ends with force.dat and
# sidecar equal to A's (the same inputs: bitwise); a copy measured as whole while it is cut = SILENT low; a refusal of
# B's own rows as "edited by hand" = UNCLEAR.
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; A=$PWD; cellIndentationFoam > log.run 2>&1 & p=$!
for i in $(seq 1 100); do [ -f postProcessing/indentation/restart.h5 ] && break; sleep 0.1; done; sleep 1; cp -a $A $W/B; echo "   copied at: A rows $(grep -vc '^#' postProcessing/indentation/force.dat) | B rows $(grep -vc '^#' $W/B/postProcessing/indentation/force.dat) sidecar $(wc -l < $W/B/postProcessing/indentation/force.dat.fnv1a64) | B lock: $(head -c 80 $W/B/.runLock | tr '\n' ' ')"
wait $p; echo "   A: rc $? End $(grep -a -c '^End' log.run)"; cd $W/B
pi; echo "   (a) B as copied: $(pk) | said: $(say 1 | cut -c1-200)"; ok_ postProcessing/indentation/force.dat
latest; tryt 600 "(b) B restarted (its copied lock in place)" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
[ "$(grep -a -c '^End' $W/try.log)" = 0 ] && { rm -f .runLock; tryt 600 "(b2) B restarted, lock removed" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"; }
for f in force.dat force.dat.fnv1a64 peaks.dat peaks.dat.fnv1a64; do echo "   $f vs A: $(cmp -s postProcessing/indentation/$f $A/postProcessing/indentation/$f && echo same || echo DIFFERS)"; done; pi; echo "   (c) B after: $(pk)"
