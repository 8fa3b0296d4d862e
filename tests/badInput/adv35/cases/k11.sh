#!/bin/bash
# k11: blast: solid/solid.h5 with 4000 bytes zeroed at 40 %, solidToFoam; the converted solid region compared with the undamaged file's
. "$(dirname "$0")/../lib.sh"
blastDone; H5=solid/solid.h5; cp -r . ../cleanCase; (cd ../cleanCase && solidToFoam $H5 > log.clean 2>&1)
dd if=/dev/zero of=$H5 bs=1 count=4000 seek=$(($(stat -c%s $H5)*40/100)) conv=notrunc 2>/dev/null
solidToFoam $H5 > log.s 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.s | head -8; tail -2 log.s; echo "rc=$rc"
diff -rq ../cleanCase/constant/solid constant/solid; for t in 0 1e-09 2e-09; do diff -rq ../cleanCase/$t/solid $t/solid; done; echo "diff done"
