#!/bin/bash
# runQueue.sh QUEUE [DIR]: adv45's: runs every "PASS ID" line of QUEUE (# comments skipped) with runOne.sh, NPAR (default
# 2) at a time; log in out/DIR.log (each line with the load average at the case's end)
q=$(realpath "$1"); cd "$(dirname "$0")"; d=${2:-A}; mkdir -p out
grep -v "^#" "$q" | awk 'NF>=2{print $1, $2}' | xargs -P ${NPAR:-2} -n 2 ./runOne.sh -o $d >> out/$d.log 2>&1
echo "$(date +%H:%M:%S) queue done" >> out/$d.log
