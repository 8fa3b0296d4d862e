#!/bin/bash
# CASETIMEOUT=900
# p26 (new, class 2/3: a case copied with hard links, `cp -al` (a cheap copy; rsync --link-dest likewise), then the copy
# restarted: a file the run appends to in place is one file in both cases): bd to A; `cp -al A B`; B restarted to 3e-9.
# Expected: A unchanged (every file's md5 as before: the run writes its files anew or refuses files with more than one
# link), B's results its own; A's postProcessing logs or solid.h5 carrying B's rows/steps = DATALOSS. (b) the same with
# the killed indentation ik (A), `cp -al A B`, B restarted to its end.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 3e-9 1e-9; rm -f .runLock; cd $W; mv blast A; cp -al A B; cd A; sums > $W/sA
cd $W/B; tryt 400 "(a) B (cp -al of A) restarted to 3e-9" cellBlastFoam; echo "   B: End $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-200)"
cd $W/A; echo "   A changed: $(changed $W/sA | cut -c1-400)"; echo "   A's coupling.dat rows $(grep -vc '^#' postProcessing/fsi/0/coupling.dat) | A's solid.h5 steps $(h5steps solid/solid.h5) | A's times $(ls -d [0-9]* | tr '\n' ' ')"
cd $W; rm -rf A B; ik; cd $W; mv ind A; cp -al A B; cd A; sums > $W/sA
cd $W/B; tryt 600 "(b) B (cp -al of the killed indentation A) restarted to its end" cellIndentationFoam; echo "   B: End $(grep -a -c '^End' $W/try.log) | said: $(msg 3 | cut -c1-200)"
cd $W/A; echo "   A changed: $(changed $W/sA | cut -c1-400)"; echo "   A's force.dat rows $(grep -vc '^#' postProcessing/indentation/force.dat)"
