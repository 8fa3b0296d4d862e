#!/bin/bash
# d66 (class 2+5, solid.h5 a symbolic link to another finished run's solid.h5 (a copy of the same case, the same inputs), restart to 3 ns): the other run's file unchanged (never written through the link); this run refused or continues with a file of its own.
. "$(dirname "$0")/../lib.sh"
bd; cd $W; cp -a blast other; md5sum other/solid/solid.h5 other/solid/solid.xmf > m; cd blast; rs; rm solid/solid.h5; ln -s $W/other/solid/solid.h5 solid/solid.h5
tryt 240 "restart with solid.h5 a link" cellBlastFoam; cont; after; echo "   the other run: $(cd $W; md5sum -c m 2>&1 | tr "\n" " "); link now: $(readlink solid/solid.h5 || echo "a file")"
