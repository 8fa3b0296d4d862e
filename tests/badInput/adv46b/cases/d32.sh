#!/bin/bash
# d32 (class 3, a read-only case): (a) no lock: cellBlastFoam, cellIndentationFoam and solidToFoam each fail at once naming the case (cannot write the lock/results), no crash; (b) a lock from another host (host nodeX) on the read-only case: named, not taken over.
. "$(dirname "$0")/../lib.sh"
bd; ro $W/blast; tryt 60 "(a) cellBlastFoam, read-only case" cellBlastFoam; tryt 60 "(a) solidToFoam, read-only case" solidToFoam solid/solid.h5
cd $W; mkdir -p i2; cp -a $ADV/idBase/. i2/; cd i2; rm -rf postProcessing; ro $W/i2; tryt 60 "(a) cellIndentationFoam, read-only case" cellIndentationFoam
cd $W; umount -l $W/blast; cd blast; printf "pid 4242\nhost nodeX\nexecutable cellBlastFoam\nstarted 2026-12-05T10:00:00\ncase %s\n" $W/blast > .runLock; cat .runLock | tr "\n" ";"; echo; ro $W/blast; tryt 60 "(b) lock of nodeX, read-only" cellBlastFoam
