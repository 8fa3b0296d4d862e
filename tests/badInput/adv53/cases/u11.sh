#!/bin/bash
# CASETIMEOUT=900
# u11 (fix19i row "a hard-linked copy of an indentation case" (solid::ownCopy), varied: the blast on 2 ranks, the water
# solver, rsync --link-dest, a hard link kept by the user outside the case): (a) pbd (2 ranks, 2e-09) copied with
# `cp -al A B`, B restarted to 3e-9 on 2 ranks; (b) waterPulseWall run to 2e-8, `cp -al A B` (rsync is not installed here), B
# restarted to 4e-8; (c) the killed indentation ik with the user's backup `ln force.dat ~/force.bak` (and peaks.dat),
# restarted to its end: the backup keeps the rows it had, the case's force.dat has its own rows. Expected: A's files
# unchanged (md5) in (a), (b); in (c) the backup unchanged and the case whole; A changed through a shared inode = DATALOSS.
. "$(dirname "$0")/../lib.sh"
pbd; rs; rm -f .runLock; cd $W; mv pblast A; cp -al A B; cd A; sums > $W/sA; cd $W/B
tryt 400 "(a) B (cp -al of the 2-rank A) restarted to 3e-9 on 2 ranks" mpirun -np 2 cellBlastFoam -parallel; echo "   B End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"; echo "   A changed: $(cd $W/A; changed $W/sA | cut -c1-400)"
cd $W; rm -rf A B; wp 2e-8; wpEnd 4e-8; cd $W; mv wp A; cp -al A B; cd A; sums > $W/sA; cd $W/B; echo "   links of A's probe log: $(stat -c %h $W/A/postProcessing/probes/0/p)"
tryt 400 "(b) B (cp -al of waterPulseWall A) restarted to 4e-8" rhoRiemannFoam; echo "   B End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"; echo "   A changed: $(cd $W/A; changed $W/sA | cut -c1-400)"
cd $W; rm -rf A B; ik; I=postProcessing/indentation; ln $I/force.dat $W/force.bak; ln $I/peaks.dat $W/peaks.bak 2>/dev/null; md5sum $W/force.bak > $W/fb; n0=$(grep -vc '^#' $W/force.bak)
tryt 600 "(c) the killed indentation restarted, the user's hard-link backup of force.dat outside" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200)"
echo "   backup: $(md5sum -c $W/fb > /dev/null 2>&1 && echo "unchanged ($n0 rows)" || echo "CHANGED (now $(grep -vc '^#' $W/force.bak) rows, $n0 before)") | case force.dat: $(forceOk $I/force.dat)"
