#!/bin/bash
# runQueue.sh QUEUE [DIR]: runs every "PASS ID" line of QUEUE (# comments skipped) with runOne.sh, two at a time; log in out/DIR.log
cd "$(dirname "$0")"; d=${2:-A}; mkdir -p out
grep -v '^#' "$1" | awk 'NF>=2{print $1, $2}' | xargs -P 2 -n 2 ./runOne.sh -o $d >> out/$d.log 2>&1
echo "$(date +%H:%M:%S) queue done" >> out/$d.log
