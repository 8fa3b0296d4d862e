#!/bin/bash
# d49 (class 5, solid.h5 of the finished preview with 4096 bytes zeroed in its middle, and one bit flipped near its end): solidToFoam refused naming the file and dataset (checksums), a restart refused too; nothing converted silently.
. "$(dirname "$0")/../lib.sh"
bd; rs; s=$(stat -c %s solid/solid.h5); dd if=/dev/zero of=solid/solid.h5 bs=1 seek=$((s/2)) count=4096 conv=notrunc 2>/dev/null; tryt 100 "(a) solidToFoam, 4 KiB zeroed" solidToFoam solid/solid.h5; ls constant; tryt 240 "(a) restart" cellBlastFoam; after
cd $W; rm -rf blast; bd; rs; s=$(stat -c %s solid/solid.h5); flip solid/solid.h5 $((s-100)); tryt 100 "(b) solidToFoam, bit near the end" solidToFoam solid/solid.h5; tryt 240 "(b) restart" cellBlastFoam; after
