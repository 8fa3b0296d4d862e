#!/bin/bash
# CASETIMEOUT=600
# l11 (new, class 2/3: adv52 p35 for the blast, with the user's explicit -overwrite): A the finished preview (bd), B a
# copy of A's inputs whose (a) postProcessing/ is a link to A's postProcessing/, (b) solid/ a link to A's solid/; B run
# from 0 with `cellBlastFoam -overwrite` (the user asks to replace B's results - which are A's); (c) B with
# postProcessing/fsi a link to A's postProcessing/fsi (a sub-folder) run from 0 without -overwrite. Expected: refused
# naming the link that leaves the case (A's results kept, md5); A's logs or solid.h5 replaced by B's run = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; rm -f .runLock; cd $W; mv blast A; cd A; sums > $W/sA
mkB() { rm -rf $W/B; cp -a $W/A $W/B; cd $W/B; rm -rf postProcessing solid [1-9]* .*overwritten*; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; }
one() { tryt 300 "$1" cellBlastFoam "${@:2}"; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"; echo "   A changed: $(cd $W/A; changed $W/sA | cut -c1-300)"; cd $W/A; sums > $W/sA; }
mkB; ln -s $W/A/postProcessing postProcessing; one "(a) B (postProcessing -> A's) cellBlastFoam -overwrite" -overwrite
mkB; ln -s $W/A/solid solid; one "(b) B (solid -> A's) cellBlastFoam -overwrite" -overwrite
mkB; mkdir postProcessing; ln -s $W/A/postProcessing/fsi postProcessing/fsi; one "(c) B (postProcessing/fsi -> A's) cellBlastFoam"
