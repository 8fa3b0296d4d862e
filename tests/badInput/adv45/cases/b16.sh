#!/bin/bash
# b16 (class 4, pulseStudy -dict of odd kinds): -dict a directory, a missing file, a FIFO, /dev/zero (endless), /dev/null (empty), a file of binary bytes: each refused within seconds naming the file and what it is; no hang, no traceback, nothing written?
. "$(dirname "$0")/../lib.sh"
study; mkfifo ../fifo; head -c 3000 /dev/urandom > ../bin
for d in system "$W/none" ../fifo /dev/zero /dev/null ../bin; do timeout -s KILL 60 pulseStudy -case . -dict "$d" > ../log.s 2>&1; echo "-dict $d: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|running' ../log.s | cut -c1-220)"; done; echo "   written: $(ls -a postProcessing 2>/dev/null | tr '\n' ' ')"
