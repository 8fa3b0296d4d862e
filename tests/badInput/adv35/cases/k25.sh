#!/bin/bash
# k25: solid.h5 (ind) zeroed in 20 places of 100 bytes spread over the file: solidToFoam must refuse or give the undamaged file's fields
. "$(dirname "$0")/../lib.sh"
indDone; H5=postProcessing/indentation/solid.h5
solidToFoam $H5 > log.clean 2>&1; mkdir ../clean; mv [0-9]* constant/solid ../clean/ 2>/dev/null
s=$(stat -c%s $H5); for i in $(seq 1 20); do dd if=/dev/zero of=$H5 bs=1 count=100 seek=$((s*i/21)) conv=notrunc 2>/dev/null; done
solidToFoam $H5 > log.s 2>&1; rc=$?; grep -A5 "FATAL\|rror" log.s | head -8; tail -2 log.s; echo "rc=$rc"
for t in $(ls ../clean | grep '^[0-9]'); do diff -rq ../clean/$t $t; done; diff -rq ../clean/solid constant/solid; echo "diff done"
