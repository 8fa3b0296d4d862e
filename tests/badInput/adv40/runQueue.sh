#!/bin/bash
# runQueue.sh QUEUE [DIR]: runs every "estimate PASS ID" line of QUEUE with runOne.sh, two cases at a time; log in out/DIR.log
cd "$(dirname "$0")"; d=${2:-A}
awk '{print $2, $3}' "$1" | xargs -P 2 -n 2 ./runOne.sh -o $d >> out/$d.log 2>&1
echo "$(date +%H:%M:%S) queue done" >> out/$d.log
