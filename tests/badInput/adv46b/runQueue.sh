#!/bin/bash
# runQueue.sh QUEUE [DIR]: runs every "PASS ID" line of QUEUE (# comments skipped) with runOne.sh, NPAR (default 2) at a
# time; log in out/DIR.log (adv43's, with NPAR: one at a time while I ran my new cases beside it)
q=$(realpath "$1"); cd "$(dirname "$0")"; d=${2:-A}; mkdir -p out
grep -v "^#" "$q" | awk 'NF>=2{print $1, $2}' | xargs -P ${NPAR:-2} -n 2 ./runOne.sh -o $d >> out/$d.log 2>&1
echo "$(date +%H:%M:%S) queue done" >> out/$d.log
