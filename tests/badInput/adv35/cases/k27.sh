#!/bin/bash
# k27: ind: a good solidToFoam conversion exists; solid.h5 then damaged (20 zeroed spots); solidToFoam re-run: the earlier converted fields must stay intact
. "$(dirname "$0")/../lib.sh"
indDone; H5=postProcessing/indentation/solid.h5
solidToFoam $H5 > log.clean 2>&1; sums > ../before
s=$(stat -c%s $H5); for i in $(seq 1 20); do dd if=/dev/zero of=$H5 bs=1 count=100 seek=$((s*i/21)) conv=notrunc 2>/dev/null; done
solidToFoam $H5 > log.s 2>&1; rc=$?; grep -A2 "FATAL" log.s | head -3; echo "rc=$rc"
sums | grep -v solid.h5 > ../after; grep -v solid.h5 ../before | diff - ../after && echo "converted fields unchanged"
