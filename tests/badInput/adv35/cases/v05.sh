#!/bin/bash
# v05: sod: riemannError on a result time with zeroed bytes in p
. "$(dirname "$0")/../lib.sh"
sodDone; t=$(foamListTimes -latestTime | tail -1); f=$t/p; dd if=/dev/zero of=$f bs=1 count=64 seek=$(($(stat -c%s $f)*60/100)) conv=notrunc 2>/dev/null
riemannError -latestTime > log.re 2>&1; rc=$?; grep -A4 "FATAL" log.re | head -6; tail -1 log.re; echo "rc=$rc"
