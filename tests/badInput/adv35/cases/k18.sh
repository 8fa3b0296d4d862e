#!/bin/bash
# k18: blast: fluidProbes p with 64 bytes zeroed mid-file, planeWave
. "$(dirname "$0")/../lib.sh"
blastDone; dd if=/dev/zero of=postProcessing/fluidProbes/0/p bs=1 count=64 seek=$(($(stat -c%s postProcessing/fluidProbes/0/p)*50/100)) conv=notrunc 2>/dev/null
planeWave -Z 20e-6 -dz 50e-9 > log.pw 2>&1; rc=$?; grep -i -A3 "error\|Traceback" log.pw | head; tail -3 log.pw; echo "rc=$rc"
