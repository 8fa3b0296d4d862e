#!/bin/bash
# k02: ind: solid.h5 with 2000 bytes zeroed at 50 %, solidToFoam; the converted fields compared with those of the undamaged file
. "$(dirname "$0")/../lib.sh"
indDone; H5=postProcessing/indentation/solid.h5
solidToFoam $H5 > log.clean 2>&1; mkdir ../clean; mv [0-9]* constant/solid ../clean/ 2>/dev/null
dd if=/dev/zero of=$H5 bs=1 count=2000 seek=$(($(stat -c%s $H5)*50/100)) conv=notrunc 2>/dev/null
solidToFoam $H5 > log.s 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.s | head -8; tail -2 log.s; echo "rc=$rc"
for t in $(ls ../clean | grep '^[0-9]'); do diff -rq ../clean/$t $t; done; echo "diff done"
h5dump -p -H $H5 2>/dev/null | grep -c CHECKSUM
