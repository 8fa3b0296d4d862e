#!/bin/bash
# g17 (class 1/4, time directories whose names are numbers at a double's edge) bd restart (latestTime, to 3e-9) with an empty directory named 1e400, then nan, then inf, then 1e-400 beside the time directories (one at a time): no floating-point exception; each refused naming the directory or ignored as no time of the run (the restart then from 2e-09, exit 0).
. "$(dirname "$0")/../lib.sh"
bd; rs; sums > ../s0
for d in 1e400 nan inf 1e-400 0x1p-30; do rm -rf 3e-09; mkdir $d; tryt 240 "directory '$d'" cellBlastFoam; echo "   times now: $(ls -d [0-9]* [a-z]* 2>/dev/null | grep -v '^log\|^constant\|^system\|^solid\|^postProcessing' | tr '\n' ' ')"; rmdir $d 2>/dev/null || rm -rf $d; done
