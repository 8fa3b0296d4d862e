#!/bin/bash
# CASETIMEOUT=900
# l07 (new, class 6: a file system out of inodes, not of bytes - many small files, a quota on files): bd restarted to
# 6e-9 (a time every 1 ns, ~20 files each) inside a tmpfs with nr_inodes = the case's files + 12 (room for less than one
# more time directory); then the case copied out and restarted again without the limit; (b) the killed indentation ik
# in a tmpfs with nr_inodes = its files + 2, restarted. Expected: each stops rc != 0 naming the file it could not create
# (No space left on device) without a signal, the last complete time kept; the later restart continues from it and
# its 3e-09/p equals the plain restart's; a time committed with a file missing, or a signal = CRASH / SILENT.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cd $W; cp -a blast ref; cd ref; tryt 400 "(0) the plain restart to 3e-9 (reference)" cellBlastFoam
ni=$(find $W/blast | wc -l); mkdir -p $W/fs; mount -t tmpfs -o size=400m,nr_inodes=$((ni + 40)) tmpfs $W/fs || echo "   mount failed"
cp -a $W/blast $W/fs/blast; cd $W/fs/blast; blastEnd 6e-9 1e-9; echo "   inodes: case $ni, free now $(df -i --output=ifree $W/fs | tail -1)"
tryt 400 "(a) restart to 6e-9 with $(df -i --output=ifree $W/fs | tail -1 | tr -d ' ') inodes left" cellBlastFoam; echo "   sig $(sig) | said: $(say 3 | cut -c1-300) | times: $(ls -d [0-9]* .[0-9]* *.incomplete 2>/dev/null | tr '\n' ' ') | marker in last: $(ls -d */.writeCommitted | tail -1)"
cd $W; cp -a fs/blast b2; umount -l $W/fs; cd b2; rm -f .runLock; blastEnd 3e-9 1e-9
tryt 400 "(a2) the copy restarted without the limit to 3e-9" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300)"; [ -f 3e-09/p ] && echo "   3e-09/p: $(cmp -s 3e-09/p $W/ref/3e-09/p && echo 'same as the plain restart' || echo DIFFERS)"
cd $W; ik; ni=$(find $W/ind | wc -l); mount -t tmpfs -o size=400m,nr_inodes=$((ni + 8)) tmpfs $W/fs; cp -a $W/ind $W/fs/ind; cd $W/fs/ind
tryt 400 "(b) the killed indentation restarted with $(df -i --output=ifree $W/fs | tail -1 | tr -d ' ') inodes left" cellIndentationFoam; echo "   sig $(sig) | said: $(say 3 | cut -c1-300)"; after
cd $W; cp -a fs/ind i2; umount -l $W/fs; cd i2; rm -f .runLock; tryt 600 "(b2) the copy restarted without the limit" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-250)"; after
